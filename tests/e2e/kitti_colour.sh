#!/usr/bin/env bash
# KITTI odometry with the colour camera (image_2, P2): the four real snippets (00, 04, 06, 08, frames
# 0-9) imported with --camera 2 and run through the full system; frame-to-frame error against the
# ground truth below KISS-ICP's on the same frames (its defaults: 20.1, 52.2, 15.5, 41.6 mm RMS).
set -u
BIN="${VLO_BIN:?}"
INI="${VLO_SRC:?}/ini"
. "$VLO_SRC/tests/e2e/lib/common.sh"
tar -xJf "$VLO_DATA/kitti_odometry_snippets.tar.xz"

for case in 00:0.0201 04:0.0522 06:0.0155 08:0.0416; do
	seq=${case%%:*} kiss=${case##*:}
	"$BIN/vlo-import" kitti-odometry --root kitti_odometry_snippets --seq "$seq" --camera 2 --out "$seq.rawlog" \
		> /dev/null || { fail "$seq: import failed"; continue; }
	rawlog-edit --info -i "$seq.rawlog" | grep -Eq "CAMERA +/ +10 " || fail "$seq: rawlog-edit does not see 10 images"
	"$BIN/vlo-run" --rawlog "$seq.rawlog" --ini "$INI/kitti-hdl64.ini" --out "out_$seq" --quiet > /dev/null ||
		{ fail "$seq: vlo-run failed"; continue; }
	"$BIN/vlo-eval" --gt "$seq.gt.tum" --est "out_$seq/trajectory_vlo.tum" --metric rpe --json "$seq.json" > /dev/null ||
		{ fail "$seq: vlo-eval failed"; continue; }
	rpe=$(jv "$seq.json" rpe_t_rmse_m)
	echo "$seq: VLO frame-to-frame RMS $rpe m (KISS-ICP $kiss m), scale valid $(jv "out_$seq/summary.json" scale_valid) of 9"
	below "$rpe" "$kiss" || fail "$seq: frame-to-frame RMS $rpe m not below KISS-ICP's $kiss m"
	[ "$(jv "out_$seq/summary.json" scale_valid)" -ge 5 ] || fail "$seq: fewer than 5 valid scale estimates"
done
finish kitti_colour
