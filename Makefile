# The README's two commands: `make run` opens the editor on a sample project,
# `make test` runs the full suite. Both set up everything first (tools/setup.sh).
SAMPLE ?= sample_projects/greeting-card/greeting-card.toml
PYTEST_ARGS ?=
# The suite runs on every core (pytest-xdist), each test module on one worker (--dist
# loadscope: a module's shared set-up, such as the fuzz corpus's run, is made once), the
# longest modules first (tests/conftest.py), the others in the order pytest collects them.
# PYTEST_WORKERS=0 runs it in one process.
PYTEST_WORKERS ?= auto

.PHONY: run test setup benchmarks clean

setup:
	@bash tools/setup.sh

run: setup
	.venv/bin/floatpage edit $(SAMPLE)

test: setup
	.venv/bin/python -m pytest -n $(PYTEST_WORKERS) --dist loadscope --no-loadscope-reorder $(PYTEST_ARGS)

benchmarks: setup
	.venv/bin/python benchmarks/physics.py
	.venv/bin/python benchmarks/render.py
	.venv/bin/python benchmarks/editor.py frames
	.venv/bin/python benchmarks/editor.py link    # starts its own sshd on 127.0.0.1 (openssh-server)

clean:
	rm -rf .venv .pytest_cache build *.egg-info
