#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, ASan + UBSan + coverage) in their own folder and runs each
# for SECONDS on the seed corpus (real files from ../shared/data, see fuzz/seeds.cpp).
#   fuzz/run.sh [SECONDS] [TARGET...]      default: 60 s, every target
#   VLO_FUZZ_BUILD=DIR  build folder (default build-fuzz); JOBS=N  build jobs (default nproc)
# Findings (crash, leak, timeout, out-of-memory, wrong error) land in DIR/findings/TARGET/; the
# corpus grows in DIR/corpus/TARGET/. Exit 1 if anything was found.
# Memory: AddressSanitizer cannot run under `ulimit -v` (it reserves terabytes of shadow memory), so
# libFuzzer's own limits stand in: -rss_limit_mb and -malloc_limit_mb (one allocation above it is a finding).
set -euo pipefail
cd "$(dirname "$0")/.."
secs=${1:-60}
shift || true
all=(rawlog rawlog_velodyne kitti_calib kitti_raw_calib kitti_times kitti_raw_timestamps kitti_poses kitti_bin tum ini rosbag)
targets=("${@:-${all[@]}}")
build=${VLO_FUZZ_BUILD:-build-fuzz}

mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	-DVLO_FUZZ=ON -DVLO_BUILD_TESTS=OFF -DVLO_BUILD_BENCH=OFF >"$build/cmake.log"
cmake --build "$build" -j "${JOBS:-$(nproc)}" --target fuzz_seeds "${targets[@]/#/fuzz_}"

found=0
printf '%-22s %10s %8s %s\n' target inputs seconds findings
for t in "${targets[@]}"; do
	corpus=$build/corpus/$t findings=$build/findings/$t seeds=$build/seeds/$t
	mkdir -p "$corpus" "$findings"
	rm -rf "$seeds"
	"$build/bin/fuzz_seeds" "$t" "$seeds" "$build/test_data"
	log=$build/findings/$t.log
	status=0
	"$build/bin/fuzz_$t" "$corpus" "$seeds" -max_total_time="$secs" -timeout=20 -rss_limit_mb=4000 \
		-malloc_limit_mb=1024 -artifact_prefix="$findings/" -print_final_stats=1 >"$log" 2>&1 || status=$?
	runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
	n=$(find "$findings" -type f | wc -l)
	where=""
	[ "$n" -ne 0 ] && where=" in $findings"
	printf '%-22s %10s %8s %s\n' "$t" "${runs:-?}" "$secs" "$n$where"
	if [ "$status" -ne 0 ] || [ "$n" -ne 0 ]; then
		found=1
		grep -m3 -E 'ERROR|SUMMARY|InputError|threw' "$log" || true
	fi
done
exit $found
