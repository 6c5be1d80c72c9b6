// SPDX-License-Identifier: MIT
// The random draws of scene synthesis. A seed must make the same scenes whatever compiler built
// the tool: draw at most once per statement (or inside a braced list, which is evaluated left to
// right), never twice among a call's arguments or an operator's operands, whose order is
// unspecified.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <random>

namespace layermod {

inline double Uniform(std::mt19937_64& rng, double low, double high) {
  return std::uniform_real_distribution<double>(low, high)(rng);
}

inline int UniformInt(std::mt19937_64& rng, int low, int high) {
  return std::uniform_int_distribution<int>(low, high)(rng);
}

// Both coordinates uniform in [low, high), y drawn first.
inline Eigen::Vector2d UniformVector2(std::mt19937_64& rng, double low, double high) {
  const double y = Uniform(rng, low, high);
  const double x = Uniform(rng, low, high);
  return {x, y};
}

// A rotation uniform over SO(3): a unit quaternion from four normal draws, w first.
inline Eigen::Matrix3d UniformRotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  const double w = normal(rng);
  const double x = normal(rng);
  const double y = normal(rng);
  const double z = normal(rng);
  return Eigen::Quaterniond(w, x, y, z).normalized().toRotationMatrix();
}

}  // namespace layermod
