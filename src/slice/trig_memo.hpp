// Remembered results of unit_vector, tan and sin, keyed by the exact bits of their argument, so
// an angle met again returns the very value computed the first time. Contact arcs bounded
// by a fixed feature's normals start and end at the same angles slice after slice, and the
// arrangement evaluates every contact arc again at its two ends: one sine and cosine each
// time without this. Direct mapped: a collision only forgets, it never answers wrong.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice {

class TrigMemo {
 public:
  TrigMemo() : units_(kSize, {0, {1.0, 0.0}}), tans_(kSize, {0, 0.0}), sins_(kSize, {0, 0.0}) {}

  // unit_vector(angle), bit for bit.
  Vec2 unit_vector(double angle) {
    const uint64_t key = std::bit_cast<uint64_t>(angle);
    UnitEntry& e = units_[slot(key)];
    if (e.key != key) e = {key, cslice::unit_vector(angle)};
    return e.unit;
  }
  // std::tan(x), bit for bit.
  double tan(double x) {
    const uint64_t key = std::bit_cast<uint64_t>(x);
    TanEntry& e = tans_[slot(key)];
    if (e.key != key) e = {key, std::tan(x)};
    return e.value;
  }
  // std::sin(x), bit for bit: an arc edge's area term takes the sine of its sweep, and a
  // contact arc cut nowhere keeps its sweep from slice to slice.
  double sin(double x) {
    const uint64_t key = std::bit_cast<uint64_t>(x);
    TanEntry& e = sins_[slot(key)];
    if (e.key != key) e = {key, std::sin(x)};
    return e.value;
  }

 private:
  static constexpr int kBits = 10;
  static constexpr size_t kSize = size_t{1} << kBits;
  static size_t slot(uint64_t key) { return size_t((key * 0x9E3779B97F4A7C15ull) >> (64 - kBits)); }

  struct UnitEntry {
    uint64_t key;  // bits of the angle
    Vec2 unit;
  };
  struct TanEntry {
    uint64_t key;
    double value;
  };
  std::vector<UnitEntry> units_;
  std::vector<TanEntry> tans_;
  std::vector<TanEntry> sins_;  // the same layout: a key and one value
};

}  // namespace cslice
