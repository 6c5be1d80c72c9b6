#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Fits the detection confidence model of core/pipeline/confidence.cpp.

Reads the outcomes of one or more `layermod eval` reports (report.json), takes every detection
with its confidence features, labels it right (the object is in the frame and the pose is
correct, ADD(-S) <= km x diameter; without depth: the projected boxes overlap, IoU >= 0.5) or wrong (a wrong pose, or an object the frame does not
show), and fits a logistic regression with a small L2 penalty by Newton's method. Prints the
coefficients as C++ for confidence.cpp and, per threshold, what accepting confidence >= t gives.

    tools/fit_confidence.py eval_a/report.json eval_b/report.json [--no-depth]

With --check nothing is fitted: the table is made from the confidences the reports hold (the
model in the code), per threshold with the recall over all targets and the share of absent
pairs (frame, object not in it) with an accepted detection: the check on sets made after a fit.
"""

import argparse
import json
import sys

import numpy as np

# In the order of ConfidenceFeatures::Names (core/pipeline/confidence.cpp).
FEATURES = ["score", "depth_fit", "depth_inlier_ratio", "visible_ratio", "occluded_ratio",
            "contradicted_ratio", "surface_continuation", "color_agreement", "icp_inlier_ratio",
            "icp_rmse", "outline_agreement"]
DEPTH_FREE = ["score", "color_agreement"]


def load(paths, label="correct"):
    rows, labels, present, stored = [], [], [], []
    counts = {"targets": 0, "absent": 0}
    for path in paths:
        with open(path) as f:
            report = json.load(f)
        for outcome in report["outcomes"]:
            is_present = outcome.get("present", True)
            counts["targets" if is_present else "absent"] += 1
            if not outcome.get("detected"):
                continue
            features = outcome["features"]
            rows.append([features[name] for name in FEATURES])
            labels.append(1.0 if is_present and outcome.get(label, False) else 0.0)
            present.append(is_present)
            stored.append(outcome.get("confidence", 0.0))
    if not rows:
        sys.exit("no detection with features in " + ", ".join(paths))
    return np.array(rows), np.array(labels), np.array(present), np.array(stored), counts


def print_table(confidence, y, present, counts):
    print("threshold  accepted  precision  right-kept  recall  absent-accepted")
    for t in [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]:
        accepted = confidence >= t
        right = (accepted & (y == 1)).sum()
        precision = right / max(1, accepted.sum())
        absent = (accepted & ~present).sum()
        print(f"{t:9.2f}  {accepted.sum():8d}  {precision:9.3f}  {right / max(1, y.sum()):10.3f}"
              f"  {right / max(1, counts['targets']):6.3f}"
              f"  {absent:6d} of {counts['absent']} ({100 * absent / max(1, counts['absent']):.1f} %)")


def fit(x, y, penalty=1e-2, iterations=50):
    design = np.hstack([np.ones((x.shape[0], 1)), x])
    w = np.zeros(design.shape[1])
    regulariser = penalty * np.eye(design.shape[1])
    regulariser[0, 0] = 0.0  # the bias is not penalised
    for _ in range(iterations):
        p = 1.0 / (1.0 + np.exp(-design @ w))
        gradient = design.T @ (p - y) + regulariser @ w
        hessian = design.T @ (design * (p * (1 - p))[:, None]) + regulariser
        step = np.linalg.solve(hessian, gradient)
        w -= step
        if np.abs(step).max() < 1e-9:
            break
    return w


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("reports", nargs="+")
    parser.add_argument("--no-depth", action="store_true",
                        help="fit the model for captures without depth (score and colour only)")
    parser.add_argument("--check", action="store_true",
                        help="fit nothing: tabulate the confidences stored in the reports")
    args = parser.parse_args()
    # Without depth the distance is only the matched layer's, so what can be known is whether the
    # detection is right in the image: the projected box overlaps the truth's (IoU >= 0.5).
    x, y, present, stored, counts = load(args.reports,
                                         "box_correct" if args.no_depth else "correct")
    print(f"{len(y)} detections: {int(y.sum())} right, {int((1 - y).sum())} wrong "
          f"({int((~present).sum())} of them on objects the frame does not show); "
          f"{counts['targets']} targets, {counts['absent']} absent pairs")
    if args.check:
        print_table(stored, y, present, counts)
        return
    used = DEPTH_FREE if args.no_depth else FEATURES
    columns = [FEATURES.index(name) for name in used]
    w = fit(x[:, columns], y)
    weights = np.zeros(len(FEATURES))
    weights[columns] = w[1:]
    confidence = 1.0 / (1.0 + np.exp(-(w[0] + x @ weights)))
    print("C++: {%.4f, {%s}}" % (w[0], ", ".join("%.4f" % v for v in weights)))
    print_table(confidence, y, present, counts)


if __name__ == "__main__":
    main()
