// What the DXF reader (dxf_reader.cpp) hands to the loop builder (dxf_loops.cpp): the
// outline pieces of one layer, each knowing the entity it came from.
#pragma once

#include <string>
#include <vector>

#include "cslice/geometry.hpp"

namespace cslice::dxf {

// Where a piece came from, for messages: "the LINE at line 57".
struct Origin {
  std::string entity;  // LINE, ARC, CIRCLE, LWPOLYLINE, POLYLINE
  int line = 0;        // 1-based line of the DXF file where the entity starts
  std::string block;   // for an entity of a block: " in block 'B' (the INSERT at line N)"
  std::string describe() const;
};

// One edge from `from` to `to`: straight (bulge 0) or an arc of bulge tan(sweep / 4).
struct Piece {
  Vec2 from, to;
  double bulge = 0.0;
  Origin origin;
};

// A loop already closed in the drawing: a closed polyline, or a circle.
struct ClosedLoop {
  std::vector<Piece> edges;  // empty for a circle
  bool circle = false;
  Vec2 center;
  double radius = 0.0;
  Origin origin;
};

struct Layer {
  std::vector<ClosedLoop> loops;
  std::vector<Piece> pieces;  // lines, arcs and open polylines' edges, to be joined
  bool empty() const { return loops.empty() && pieces.empty(); }
};

// A loop as the pair file writes it: vertices with the bulge of the edge each starts, or a
// circle; `origin` names the entities it was made of.
struct OutLoop {
  std::vector<Piece> edges;
  bool circle = false;
  Vec2 center;
  double radius = 0.0;
  std::string origin;
};

// Joins a layer's pieces end to end (ends within `join` meet, each with exactly one other)
// and adds its closed loops. Returns an empty string, or why it cannot (an open end, ends
// meeting three or more at a point).
std::string build_loops(const Layer& layer, double join, std::vector<OutLoop>& out);

}  // namespace cslice::dxf
