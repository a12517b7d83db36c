# The two commands of the README:
#   make run    install deps, build, and replay the project's own sample data -> results/sample/
#   make test   install deps, build, and run every test
#   make test-sanitize   the unit and e2e tests built with ASan + UBSan in build-asan/ (doc/ROBUSTNESS.md)
BUILD ?= build
JOBS  ?= $(shell nproc)

.PHONY: all deps build run test test-sanitize test-sanitize-ci check-format clean
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

# Its own build folder; any sanitizer report fails the test that caused it. Suppressions (with the reason
# for each) are for reports inside MRPT, PCL or OpenCV only: tests/sanitizers/.
SAN_BUILD ?= build-asan
SAN_SUPP  := $(CURDIR)/tests/sanitizers
SAN_ENV   := ASAN_OPTIONS=detect_leaks=1:abort_on_error=0:strict_string_checks=1:detect_stack_use_after_return=0 \
	LSAN_OPTIONS=suppressions=$(SAN_SUPP)/lsan.supp:print_suppressions=0 \
	UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1:suppressions=$(SAN_SUPP)/ubsan.supp \
	VLO_FUZZ_INPUTS=500 TEST_TMPDIR=$(CURDIR)/$(SAN_BUILD)/tmp/
# SAN_TESTS: a ctest regex to run a subset (e.g. 'Fuzz|Rawlog|Kitti|CorruptInput|e2e_import') when CI time is short.
# SAN_TARGETS: build only these (e.g. the unit tests 'test_core test_io'); SAN_EXCLUDE then leaves out the tests
# of what was not built ('_NOT_BUILT|^e2e_'). CI's lean subset: SAN_CI below.
SAN_TESTS ?= .
SAN_TARGETS ?= all
SAN_EXCLUDE ?= ^$$
test-sanitize: deps
	cmake -S . -B $(SAN_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVLO_SANITIZE=ON -DVLO_BUILD_BENCH=OFF
	cmake --build $(SAN_BUILD) -j $(JOBS) --target $(SAN_TARGETS)
	mkdir -p $(SAN_BUILD)/tmp
	cd $(SAN_BUILD) && $(SAN_ENV) ctest --output-on-failure -j $(JOBS) -R '$(SAN_TESTS)' -E '$(SAN_EXCLUDE)' --output-log ctest.log
	@if grep -E '\*\*\*Skipped' $(SAN_BUILD)/ctest.log; then echo "make test-sanitize: tests were skipped (see above)"; exit 1; fi

# Run by CI (.ci/run, after make test): the unit tests of core, io, kernel under ASan + UBSan; the whole suite
# does not fit CI's time on 2 cores (doc/ROBUSTNESS.md).
test-sanitize-ci:
	$(MAKE) test-sanitize SAN_TARGETS='test_core test_io test_kernel' SAN_EXCLUDE='_NOT_BUILT|^e2e_'

# The code keeps .clang-format (Debian's clang-format 14); `clang-format -i FILE` formats a file.
check-format: deps
	./scripts/check-format.sh

clean:
	rm -rf $(BUILD) $(SAN_BUILD) results
