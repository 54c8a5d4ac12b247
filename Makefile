# Two set-up-free commands:  `make demo` (generate and validate objects) and `make test`.
# Each creates .venv and installs what it needs on a fresh Debian machine.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
OUT    ?= infmob_out
COUNT  ?= 3

.PHONY: demo test sysdeps clean

# System libraries: libGL (sapien's opencv), Mesa >= 25 lavapipe (Vulkan on the CPU, for previews), chromium (gallery test).
sysdeps:
	@bash .ci/sysdeps.sh

$(STAMP): pyproject.toml constraints.txt | sysdeps
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install -q --upgrade pip
	# torch first, pinned: mani-skill then finds it satisfied (another torch pulls gigabytes of CUDA)
	$(BIN)/pip install -q torch==2.13.0
	$(BIN)/pip install -q -c constraints.txt -e ".[sim,dev,ray,simready]"
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/infmob generate all --count $(COUNT) --out $(OUT)
	$(BIN)/infmob validate --sim --simready $(OUT)
	$(BIN)/infmob preview --sheet $(OUT) --out $(OUT)/contact_sheet.png

test: $(STAMP)
	$(BIN)/ruff check .
	$(BIN)/python -m pytest -q -n auto --dist loadgroup

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache
