# The two commands of the README:
#   make run    install deps, build, and replay the project's own sample data -> results/sample/
#   make test   install deps, build, and run every test
BUILD ?= build
JOBS  ?= $(shell nproc)

.PHONY: all deps build run test clean
all: build

deps:
	@./scripts/install-deps.sh

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

run: build
	./scripts/run-sample.sh $(BUILD)/bin results/sample

# A skipped test fails `make test` (CI): every test's data and apps must be there.
test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS) --output-log ctest.log
	@if grep -E '\*\*\*Skipped' $(BUILD)/ctest.log; then echo "make test: tests were skipped (see above)"; exit 1; fi

clean:
	rm -rf $(BUILD) results
