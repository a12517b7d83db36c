#!/usr/bin/env python3
"""A KITTI ground truth (camera-0 poses, 3x4 per line) as a TUM file in the vehicle frame, and optionally a
drifting estimate made from it: each frame-to-frame motion scaled by SCALE in translation and followed by
YAW rad about the vehicle's z axis. For example plots and checks of vlo-eval; no numpy needed.

usage: kitti_drifted_estimate.py POSES.txt TIMES.txt CALIB.txt OUT.tum [SCALE YAW]"""
import math
import sys


def mul(a, b):
    """Product of two 4x4 matrices (lists of rows)."""
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def inv(m):
    """Inverse of a rigid 4x4 transform."""
    r = [[m[j][i] for j in range(3)] for i in range(3)]
    t = [-sum(r[i][k] * m[k][3] for k in range(3)) for i in range(3)]
    return [r[0] + [t[0]], r[1] + [t[1]], r[2] + [t[2]], [0, 0, 0, 1]]


def rows(numbers):
    v = [float(x) for x in numbers]
    return [v[0:4], v[4:8], v[8:12], [0, 0, 0, 1]]


def quaternion(m):
    """(qx, qy, qz, qw) of the rotation part (Shepperd's method)."""
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = 2 * math.sqrt(tr + 1)
        return ((m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, s / 4)
    i = max(range(3), key=lambda k: m[k][k])
    j, k = (i + 1) % 3, (i + 2) % 3
    s = 2 * math.sqrt(1 + m[i][i] - m[j][j] - m[k][k])
    q = [0.0, 0.0, 0.0]
    q[i], q[j], q[k] = s / 4, (m[j][i] + m[i][j]) / s, (m[k][i] + m[i][k]) / s
    return (q[0], q[1], q[2], (m[k][j] - m[j][k]) / s)


def main():
    if len(sys.argv) not in (5, 7):
        sys.exit(__doc__)
    poses, times, calib, out = sys.argv[1:5]
    scale, yaw = (float(sys.argv[5]), float(sys.argv[6])) if len(sys.argv) == 7 else (1.0, 0.0)
    tr = next(rows(l.split()[1:]) for l in open(calib) if l.startswith("Tr:"))
    tr_inv = inv(tr)
    vehicle = [mul(mul(tr_inv, rows(l.split())), tr) for l in open(poses) if l.strip()]
    stamps = [float(l) for l in open(times) if l.strip()]
    c, s = math.cos(yaw), math.sin(yaw)
    drift = [[c, -s, 0, 0], [s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]
    est = [vehicle[0]]
    for a, b in zip(vehicle, vehicle[1:]):
        step = mul(inv(a), b)
        for i in range(3):
            step[i][3] *= scale
        est.append(mul(mul(est[-1], step), drift))
    with open(out, "w") as f:
        for t, m in zip(stamps, est):
            f.write("%.6f %.6f %.6f %.6f %.9f %.9f %.9f %.9f\n" % ((t, m[0][3], m[1][3], m[2][3]) + quaternion(m)))


main()
