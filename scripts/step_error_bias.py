#!/usr/bin/env python3
"""Frame-to-frame error of estimated trajectories, per component: its mean (a bias that accumulates
into drift) and RMS. The error of step k is GT_step^-1 * EST_step, in the vehicle frame of frame k;
angles are its yaw, pitch and roll (ZYX) in degrees. TUM files with the same frames, in order.

usage: step_error_bias.py GT.tum EST.tum [EST2.tum ...]
"""
import math
import sys


def load(path):
    poses = []
    for line in open(path):
        if line.startswith('#') or not line.strip():
            continue
        v = [float(x) for x in line.split()]
        poses.append((v[1:4], v[4:8]))
    return poses


def rotation(q):
    x, y, z, w = q
    return [[1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)]]


def matmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def transpose(a):
    return [[a[j][i] for j in range(3)] for i in range(3)]


def apply(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]


def relative(a, b):
    """a^-1 b for poses (R, t)."""
    rt = transpose(a[0])
    return matmul(rt, b[0]), apply(rt, [b[1][i] - a[1][i] for i in range(3)])


def steps(poses):
    p = [(rotation(q), t) for t, q in poses]
    return [relative(p[k], p[k + 1]) for k in range(len(p) - 1)]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    gt = steps(load(sys.argv[1]))
    names = ['dx', 'dy', 'dz', 'yaw', 'pitch', 'roll']
    for path in sys.argv[2:]:
        est = steps(load(path))
        if len(est) != len(gt):
            sys.exit(f'{path}: {len(est) + 1} poses, the ground truth has {len(gt) + 1}')
        errors = []
        for g, e in zip(gt, est):
            r, t = relative(g, e)
            errors.append(t + [math.degrees(math.atan2(r[1][0], r[0][0])),
                               math.degrees(math.asin(max(-1.0, min(1.0, -r[2][0])))),
                               math.degrees(math.atan2(r[2][1], r[2][2]))])
        n = len(errors)
        mean = [sum(x[k] for x in errors) / n for k in range(6)]
        rms = [math.sqrt(sum(x[k] ** 2 for x in errors) / n) for k in range(6)]
        print(path)
        print('  mean ' + ' '.join(f'{k} {m:+.2e}' for k, m in zip(names, mean)) + '  [m, deg]')
        print('  rms  ' + ' '.join(f'{k} {r:.4f}' for k, r in zip(names, rms)))


if __name__ == '__main__':
    main()
