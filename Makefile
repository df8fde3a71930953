# Two commands on a fresh machine: `make demo` and `make test`.
PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
BROWSER := $(VENV)/.browser
OUT    ?= demo-output

.PHONY: demo test test-all bench lint clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install -q --upgrade pip
	$(BIN)/python -m pip install -q -e '.[dev,cad,sweep]' || $(BIN)/python -m pip install -q -e '.[dev,sweep]' \
	  || $(BIN)/python -m pip install -q -e '.[dev]'
	touch $(STAMP)

demo: $(STAMP)
	$(BIN)/juncture demo -o $(OUT)

# The report's browser test needs headless chromium: install Debian's where apt-get and root
# are available; elsewhere that one test says it was skipped and why.
$(BROWSER):
	@if command -v chromium >/dev/null 2>&1; then :; \
	elif command -v apt-get >/dev/null 2>&1 && [ "$$(id -u)" = 0 ]; then \
	  (apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
	    --no-install-recommends chromium >/dev/null) || echo "note: chromium not installed"; \
	else echo "note: no apt-get/root: the browser test will be skipped"; fi
	@touch $@

# The tests run on every core (pytest-xdist); the benchmarks alone, one at a time.
test: $(STAMP) $(BROWSER)
	$(BIN)/python -m pytest -q -n auto --dist worksteal -m "not slow"

test-all: $(STAMP) $(BROWSER)
	HYPOTHESIS_PROFILE=explore $(BIN)/python -m pytest -q -n auto --dist worksteal

bench: $(STAMP)
	$(BIN)/python -m pytest -q benchmarks --benchmark-only

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks

clean:
	rm -rf $(VENV) $(OUT) build *.egg-info src/*.egg-info .pytest_cache .benchmarks
