#!/usr/bin/env bash
# vlo-run end to end, the full system (mode vlo): a short simulated HDL-64 drive whose camera is
# blinded for a few frames. The VLO trajectory must stay within bounds, the scale-corrected VO must
# be metric (SE(3) alignment only), LOAM must take the VO's motion as its guess except while the VO
# is lost (constant velocity then), and bootstrapping off must give the constant-velocity baseline.
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"

FRAMES=60
"$BIN/vlo-sim" --scenario urban --lidar hdl64 --frames $FRAMES --seed 5 --no-realism --blackout 30:36 --out drive.rawlog --quiet ||
	{ echo "FAIL: vlo-sim"; exit 1; }

"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out vlo --gt drive.gt.tum --quiet \
	--set pipeline.mode=vlo --set pipeline.scale_snapshot_every=20 || { echo "FAIL: vlo-run"; exit 1; }
for f in trajectory_vlo.tum trajectory_vo.tum frames.csv map.pcd run.ini summary.json snapshots/topdown.png \
	snapshots/scale_000020.png; do
	[ -s "vlo/$f" ] || fail "$f missing"
done
[ "$(wc -l < vlo/trajectory_vlo.tum)" -eq $FRAMES ] || fail "trajectory_vlo.tum does not have $FRAMES poses"
# report.md names only files that exist, and embeds the snapshots, the stage times and the ATE view.
for t in $(grep -o '](\([^)]*\))' vlo/report.md | sed 's/^](//; s/)$//'); do
	[ -s "vlo/$t" ] || fail "report.md links $t, which does not exist"
done
for f in snapshots/topdown.png snapshots/time_per_stage.png snapshots/ate_vlo.png trajectory_vlo.tum; do
	grep -qF "($f)" vlo/report.md || fail "report.md does not link $f"
done
grep -qx "report.md" vlo/.vlo-run-files || fail "report.md is not in .vlo-run-files"
grep -q '^source *= *external' vlo/run.ini || fail "run.ini does not show the external LOAM prior"

"$BIN/vlo-eval" --gt drive.gt.tum --est vlo/trajectory_vlo.tum --kitti-lengths 10,20,30 --json vlo.json > /dev/null ||
	fail "vlo-eval of the VLO trajectory"
# The VO knows nothing of the blind frames: each of its two maps is checked on its own (SE(3) only).
awk '$1 < 2.95' vlo/trajectory_vo.tum > vo_map1.tum
awk '$1 > 3.55' vlo/trajectory_vo.tum > vo_map2.tum
[ "$(wc -l < vo_map1.tum)" -ge 25 ] && [ "$(wc -l < vo_map2.tum)" -ge 20 ] || fail "scale-corrected VO has too few poses"
echo "vlo: kitti_t_err_pct=$(jv vlo.json kitti_t_err_pct) ate_rmse_m=$(jv vlo.json ate_rmse_m)"
below "$(jv vlo.json kitti_t_err_pct)" 1.5 || fail "VLO KITTI t_err above 1.5 %"
below "$(jv vlo.json ate_rmse_m)" 0.3 || fail "VLO ATE above 0.3 m"
for m in vo_map1 vo_map2; do
	"$BIN/vlo-eval" --gt drive.gt.tum --est $m.tum --align se3 --metric ate --json $m.json > /dev/null ||
		fail "vlo-eval of $m"
	echo "scale-corrected VO, $m (SE(3)): ate_rmse_m=$(jv $m.json ate_rmse_m) ate_pct=$(jv $m.json ate_pct_of_length)"
	below "$(jv $m.json ate_pct_of_length)" 1 || fail "scale-corrected VO ($m) ATE above 1 % of the path"
done
valid=$(jv vlo/summary.json scale_valid)
echo "scale estimates valid: $valid"
below 20 "$valid" || fail "fewer than 20 valid scale estimates"

# frames.csv's column order as doc/FORMATS.md documents it, and no signed zero.
head -1 vlo/frames.csv | python3 -c '
import sys
h = sys.stdin.read().strip().split(",")
modules = [c.split("_")[0] for c in h[5:] if not c.startswith("ms_")]
timing = [c for c in h if c.startswith("ms_")]
ok = h[:5] == ["frame", "t", "x", "y", "z"] and h[-1] == "ms_total" and h[len(h) - len(timing):] == timing
ok = ok and modules == sorted(modules, key=["vo", "scale", "lo"].index)
sys.exit(0 if ok else "header: " + ",".join(h))' || fail "frames.csv column order"
! grep -qE '(^|,)-0(\.0+)?(,|$)' vlo/frames.csv || fail "frames.csv holds a negative zero: $(grep -m1 -oE '(^|,)-0(\.0+)?(,|$)' vlo/frames.csv)"

# Rows whose vo_reason holds a comma keep their later columns: every lo_prior is one of LOAM's sources.
grep -q '"initialised (.*,' vlo/frames.csv || fail "no quoted vo_reason with a comma in frames.csv"
[ "$(column vlo/frames.csv lo_prior | grep -cvxE 'none|constant_velocity|external|cold_start')" -eq 0 ] ||
	fail "lo_prior holds something else than a prior source (columns shifted?)"

# LOAM's guess per frame: the VO's metric motion when there is one, constant velocity otherwise.
paste -d' ' <(column vlo/frames.csv frame) <(column vlo/frames.csv vo_metric_motion) <(column vlo/frames.csv lo_prior) > prior.txt
awk '$1 >= 30 && $1 < 36 && $3 != "constant_velocity" { bad++ } END { exit bad > 0 }' prior.txt ||
	fail "LOAM did not fall back to constant velocity while the camera was blind"
awk '$2 == 1 && $3 != "external" { bad++ } END { exit bad > 2 }' prior.txt ||
	fail "LOAM ignored the VO's metric motion"
ext=$(awk '$3 == "external"' prior.txt | wc -l)
echo "frames bootstrapped by the VO: $ext of $FRAMES"
below 35 "$ext" || fail "fewer than 35 frames bootstrapped by the VO"

"$BIN/vlo-run" --rawlog drive.rawlog --ini "$INI/sim-hdl64.ini" --out noboot --quiet \
	--set pipeline.mode=vlo --set pipeline.bootstrapping=false --set pipeline.snapshots=false || fail "vlo-run, bootstrapping off"
[ "$(column noboot/frames.csv lo_prior | grep -c external)" -eq 0 ] || fail "bootstrapping off still used the VO"
[ -s noboot/trajectory_vo.tum ] || fail "bootstrapping off: no scale-corrected VO"

finish run_vlo
