// SPDX-License-Identifier: MIT
#pragma once

// The cameras the tests share, each with the values its tests were written for.

#include "geometry/camera.h"

namespace layermod::test {

// LineMOD's Kinect, exactly as in its camera.json.
inline PinholeCamera KinectCamera() { return {572.4114, 573.57043, 325.2611, 242.04899, 640, 480}; }

// The Kinect rounded to 0.1 px.
inline PinholeCamera RoundedKinectCamera() { return {572.4, 573.6, 325.3, 242.0, 640, 480}; }

// VGA with square pixels and the principal point at the image centre.
inline PinholeCamera VgaCamera() { return {572.0, 572.0, 319.5, 239.5, 640, 480}; }

// VGA with round numbers, for projections worked out by hand.
inline PinholeCamera RoundVgaCamera() { return {500.0, 500.0, 320.0, 240.0, 640, 480}; }

// 320 x 240: the small synthetic datasets and the archives trained for them.
inline PinholeCamera SmallCamera() { return {286.2, 286.8, 162.4, 120.8, 320, 240}; }

// 64 x 48: fuzz seeds.
inline PinholeCamera TinyCamera() { return {60.0, 60.0, 31.5, 23.5, 64, 48}; }

// 80 x 60 with more digits than a float keeps, to check what files store.
inline PinholeCamera ManyDigitsCamera() { return {80.123456789, 81.5, 39.75, 29.25, 80, 60}; }

}  // namespace layermod::test
