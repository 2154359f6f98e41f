# Counter-Steer: every entry point. Each target provisions what it needs first, so
# `make play` and `make test` work on a bare machine. See README.md.
SHELL := bash
.DEFAULT_GOAL := help
.PHONY: help setup build play test pictures bench experiment train clean-learn export export-check export-windows export-check-windows clean

help: ## List the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | awk -F':.*## ' '{printf "  make %-21s %s\n", $$1, $$2}'

setup: ## Check the machine (tools/preflight.sh), then provision Godot 4.6, ODE and the Python tools (idempotent)
	@tools/preflight.sh
	@tools/provision-godot.sh
	@tools/build-ode.sh
	@tools/provision-python.sh

build: setup ## Build the native extension (release) and import the project
	@tools/build.sh

play: build ## Launch the game window
	@tools/play.sh

test: build ## Run every check: Rust fmt/clippy/tests, gdlint, GDScript suites, screenshots, export
	@tools/test.sh

pictures: build ## Draw every picture the docs show from the game as it is now into docs/images/ (tools/pictures.sh)
	@tools/pictures.sh --docs

bench: build ## Print the performance figures, planning and frame time (see docs/benchmarks.md); BIKE=FILE for another bike
	@tools/cargo run --release --quiet -p cpbp-core --bin cpbp-bench -- $(if $(BIKE),--bike $(abspath $(BIKE)))
	@tools/frame-time.sh

experiment: build ## The thesis's evaluation on the game's physics, headless (docs/experiment.md; ARGS="--out docs/experiment")
	@tools/experiment all $(ARGS)

train: build ## Train the learned controller from nothing and evaluate it (docs/learned-controller.md); BIKE=FILE for a bike's, BIKE=all for every bike's
	@tools/train.sh

export: build ## Export the Linux build into build/linux/ (a portable engine: built once, ~40 min)
	@PORTABLE_TEMPLATE=1 tools/export.sh

export-check: build ## Export, then ride the build in a clean Debian 12 desktop root
	@tools/export-check.sh

export-windows: build ## Export the Windows build into build/windows/ (cross-built once, ~30 min)
	@tools/export-windows.sh

export-check-windows: build ## Export for Windows, then ride that build under Wine in a clean Debian 13 root
	@tools/export-check.sh windows

clean-learn: ## Remove the learned controller's training data and checkpoints (in the cache)
	rm -rf "$${LEARN_DATA:-$${COUNTER_STEER_CACHE:-$${XDG_CACHE_HOME:-$$HOME/.cache}/counter-steer}/learn}"

clean: ## Remove build products (not the provisioning cache, nor the training data)
	rm -rf build native/target addons/cpbp/bin/*.so addons/cpbp/bin/*.dll .godot
