#!/usr/bin/env bash
# System libraries infmob-usd needs on Debian: libGL (sapien pulls opencv-python, which loads it)
# and a Vulkan device for the preview renderer: Mesa >= 25 lavapipe, from <codename>-backports on
# Debian 12 (its stock Mesa 22 lavapipe cannot run SAPIEN's renderer); and Chromium, which the gallery's
# browser test drives through Playwright (never `playwright install`: the system browser is used).
# Idempotent; quiet when done.
set -euo pipefail
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
have_mesa() {
  local v
  v=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || true)
  [ -n "$v" ] && dpkg --compare-versions "$v" ge 25
}
need=()
ldconfig -p | grep -q 'libGL.so.1 ' || need+=(libgl1 libegl1)
command -v chromium >/dev/null || need+=(chromium)
if [ ${#need[@]} -eq 0 ] && have_mesa; then exit 0; fi
if ! command -v apt-get >/dev/null; then
  echo "sysdeps: not a Debian system; install libGL, a Mesa >= 25 Vulkan driver and chromium yourself" >&2
  exit 0
fi
. /etc/os-release
echo "sysdeps: installing ${need[*]:-} mesa-vulkan-drivers (>= 25)"
if ! have_mesa && ! grep -rqs "${VERSION_CODENAME}-backports" /etc/apt/sources.list /etc/apt/sources.list.d/; then
  # the backports suite from the mirror this machine already uses
  uri=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/debian.sources 2>/dev/null || true)
  [ -n "$uri" ] || uri=$(awk '$1 == "deb" {print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
  echo "deb $uri ${VERSION_CODENAME}-backports main" | $SUDO tee /etc/apt/sources.list.d/backports.list >/dev/null
fi
$SUDO apt-get update -qq
if [ ${#need[@]} -gt 0 ]; then
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${need[@]}" >/dev/null
fi
if ! have_mesa; then
  $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq -t "${VERSION_CODENAME}-backports" \
    mesa-vulkan-drivers libvulkan1 >/dev/null \
    || $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq mesa-vulkan-drivers libvulkan1 >/dev/null
fi
have_mesa || echo "sysdeps: Mesa >= 25 Vulkan not available: previews will be skipped" >&2
