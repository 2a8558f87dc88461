// A vertical decomposition of one free component of a slice into curved trapezoids (each
// bounded below and above by one x-monotone piece of the component's boundary, left and
// right by vertical walls through boundary vertices and arc extremes), and routes through
// it from trapezoid to trapezoid across the walls. Exact arcs, no polygonal approximation.
#pragma once

#include <vector>

#include "cslice/slice.hpp"

namespace cslice::path_detail {

// A piece of a route inside one trapezoid, from one point of its closure to another.
struct Leg {
  int trap = 0;
  Vec2 from, to;
  int door_from = -1, door_to = -1;  // the doors it leaves and enters by, or -1
};

class TrapezoidMap {
 public:
  // `frame` stands in for infinity around an unbounded component: it must hold the
  // component's cycles and every point to be routed. Doors (the open parts of walls shared by
  // two trapezoids) narrower than min_door are closed: no free path with clearance above
  // min_door / 2 can cross them. `eps` merges walls closer than it.
  TrapezoidMap(const FreeComponent& component, const Box& frame, double eps, double min_door);

  bool covers(Vec2 p) const;
  // Legs from p to q through open doors, none through a banned door; empty if p or q is not
  // in the component or no route is left. Shortest through the doors' midpoints.
  std::vector<Leg> route(Vec2 p, Vec2 q, const std::vector<char>& banned) const;
  // The point at t in [0, 1] along a leg: x linear, and y at a linearly changing fraction of
  // the trapezoid's height, so the whole leg stays inside the trapezoid.
  Vec2 at(const Leg& leg, double t) const;
  int trapezoid_count() const { return static_cast<int>(traps_.size()); }
  int door_count() const { return static_cast<int>(doors_.size()); }

 private:
  struct Piece {
    Curve curve;
    bool floor = false;  // free space above it (it runs towards +x)
    bool upper = false;  // an arc on the upper half of its circle
    double x0 = 0.0, x1 = 0.0;
    int e0 = 0, e1 = 0;  // walls at its ends
  };
  struct Trap {
    int slab = 0, lo = 0, hi = 0;  // pieces below and above
  };
  struct Door {
    Vec2 at;
    int left = 0, right = 0;  // trapezoids
  };

  void add_piece(const Curve& c);
  void add_monotone(const Curve& c);
  void build_walls(double eps);
  void build_trapezoids();
  void build_doors(double min_door);
  double y_at(int piece, double x) const;
  int locate(Vec2 p) const;
  double fraction(int trap, Vec2 p) const;

  bool bounded_ = true;
  Box frame_;
  std::vector<Piece> pieces_;
  std::vector<double> walls_;  // x of every wall, increasing; slab j lies between j and j + 1
  std::vector<Trap> traps_;
  std::vector<std::vector<int>> slab_traps_;  // bottom to top
  std::vector<Door> doors_;
  std::vector<std::vector<int>> trap_doors_;
  double eps_ = 0.0;
};

}  // namespace cslice::path_detail
