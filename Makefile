# Two set-up-free commands:  `make demo` (generate and validate objects) and `make test`.
# Each creates .venv and installs what it needs on a fresh Debian machine.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
OUT    ?= infmob_out
COUNT  ?= 3

.PHONY: demo test sysdeps clean

# System libraries: opencv-python (pulled by sapien) needs libGL.so.1.
sysdeps:
	@if ! ldconfig -p | grep -q 'libGL.so.1 '; then \
	  echo "installing libgl1 (needed by sapien's opencv)"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq libgl1 libegl1 >/dev/null; \
	fi

$(STAMP): pyproject.toml | sysdeps
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	# torch first, pinned: mani-skill then finds it satisfied (another torch pulls gigabytes of CUDA)
	$(BIN)/pip install -q torch==2.13.0
	$(BIN)/pip install -q -e ".[sim,dev,ray]"
	touch $(STAMP)

demo: $(STAMP)
	@for c in $$($(BIN)/infmob list); do \
	  $(BIN)/infmob generate $$c --count $(COUNT) --out $(OUT) || exit 1; \
	done
	$(BIN)/infmob validate $(OUT)

test: $(STAMP)
	$(BIN)/python -m pytest -q

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache
