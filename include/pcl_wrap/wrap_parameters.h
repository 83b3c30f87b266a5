// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>

namespace pcl_wrap
{

/** \brief How sinks (large empty spheres, docs/design.md §6) are deleted after the basic
  * construction to wrap tighter and open tunnels. */
enum class SinkDeletion : std::uint8_t
{
  front, ///< sinks larger than the threshold whose basin reaches the surface: never a cavity
  global ///< every sink larger than the threshold (or the J largest): may carve cavities
};

/** \brief What the construction returns as its surface. */
enum class Output : std::uint8_t
{
  surface, ///< an oriented 2-manifold through the points (see docs/surface.md), the default:
           ///< closed, the boundary of the tetrahedra labelled inside; for a single layer (a
           ///< terrain, a scan seen from one side) open, one sheet through the points
  closed,  ///< the same, but a single layer too closed: a two-sided shell, its points copied per side
  raw      ///< W = Bd X exactly as the paper defines it (pinches, sheets, dangling edges)
};

/** \brief A closed region of space (a ball or an axis-aligned box) for local modification. */
struct Region
{
  enum class Shape : std::uint8_t
  {
    everywhere, ///< no restriction
    sphere,     ///< values: centre x, y, z and radius
    box         ///< values: lowest corner x, y, z, then highest corner x, y, z
  };
  Shape shape = Shape::everywhere;
  std::array<double, 6> values{};

  static Region sphere (double x, double y, double z, double r) { return {Shape::sphere, {x, y, z, r, 0, 0}}; }
  static Region box (double x0, double y0, double z0, double x1, double y1, double z1)
  {
    return {Shape::box, {x0, y0, z0, x1, y1, z1}};
  }

  /** \brief Is the point (x, y, z) in the region (boundary included)? */
  bool contains (const std::array<double, 3>& p) const
  {
    const auto& v = values;
    switch (shape)
    {
    case Shape::sphere:
      return (p[0] - v[0]) * (p[0] - v[0]) + (p[1] - v[1]) * (p[1] - v[1]) + (p[2] - v[2]) * (p[2] - v[2]) <=
             v[3] * v[3];
    case Shape::box:
      return v[0] <= p[0] && p[0] <= v[3] && v[1] <= p[1] && p[1] <= v[4] && v[2] <= p[2] && p[2] <= v[5];
    default: return true;
    }
  }
};

/** \brief Which sinks (empty spheres, §8) the construction deletes to wrap tighter: none (the
  * basic wrap, the default), those larger than a size, or the J largest. One value, so that
  * setting one threshold replaces the other. */
class Threshold
{
public:
  enum class Kind : std::uint8_t
  {
    none,            ///< the basic wrap
    size,            ///< sinks whose size (squared radius of their sphere) exceeds value()
    relative_radius, ///< sinks whose radius exceeds value() times the spacing (medianSpacing())
    largest          ///< the count() largest sinks, wherever they are (always a global deletion)
  };

  Threshold () = default;
  /** \brief Sinks of squared radius larger than \a delta (+inf: none). */
  static Threshold size (double delta) { return {Kind::size, delta, 0}; }
  /** \brief Sinks of radius larger than \a radius. */
  static Threshold radius (double radius) { return {Kind::size, radius * radius, 0}; }
  /** \brief Sinks of radius larger than \a factor times the median nearest-neighbour distance:
    * the same sinks at any scale. */
  static Threshold relativeRadius (double factor) { return {Kind::relative_radius, factor, 0}; }
  /** \brief The \a count largest sinks (omega, the outside, is always deleted and not counted). */
  static Threshold largest (std::size_t count) { return {Kind::largest, 0.0, count}; }

  Kind kind () const { return kind_; }
  double value () const { return value_; }
  std::size_t count () const { return count_; }
  /** \brief Does it delete anything? */
  bool deletes () const
  {
    return kind_ == Kind::relative_radius || kind_ == Kind::largest ||
           (kind_ == Kind::size && value_ < std::numeric_limits<double>::infinity ());
  }

private:
  Threshold (Kind kind, double value, std::size_t count) : kind_ (kind), value_ (value), count_ (count) {}
  Kind kind_ = Kind::none;
  double value_ = 0.0;
  std::size_t count_ = 0;
};

/** \brief Every tunable of the Wrap construction, with its default written once here.
  *
  * The PCL class, the command-line tool and the ROS node all read their defaults from this
  * struct, so that no default is written twice.
  */
struct WrapParameters
{
  /** \brief Keep the whole complex (every Delaunay simplex with its class and whether it is in X)
    * in the result. Off unless asked: it costs memory and time proportional to the triangulation
    * (hundreds of MB at a million points); the surface is always kept. */
  bool keep_complex = false;

  /** \brief Threads for the parallel stages, in a TBB task arena of this size that lasts the
    * call (other TBB users in the process keep their own); 0 runs in the caller's arena (by
    * default all cores). The result does not depend on it. */
  unsigned num_threads = 0;

  /** \brief Every weight is multiplied by this before use. A weight is a squared radius: the
    * power distance from point p is |x - p|^2 - w_p. */
  double weight_scale = 1.0;

  /** \brief Which sinks to delete; by default none (the basic wrap). */
  Threshold threshold;
  /** \brief How sinks above a size threshold are deleted (see SinkDeletion). */
  SinkDeletion deletion = SinkDeletion::front;

  /** \brief Local modification (§8): front deletion starts only from the part of W inside this
    * region (its simplices whose vertices all lie in it), with the threshold above; the rest of
    * the surface changes only where a basin reaching into the region also reaches it. Front mode
    * only. */
  Region region;

  /** \brief The surface returned: the default surface or the paper's W. X, the deletion and the
    * filtration are the same either way. */
  Output output = Output::surface;

  /** \brief Where the points were seen from (a sensor's position, PCL's sensor_origin_): an open
    * sheet (Output::surface of a single layer) faces it. Without it, a sheet faces up (+z), and a
    * sheet with no up or down (a vertical wall) out of the solid its points close with their
    * convex hull. */
  std::optional<std::array<double, 3>> viewpoint;

  /** \brief Raw output only: a closed combinatorial 2-manifold: W's triangles, split where W touches itself
    * (pinch edges and vertices get copies of their points, appended after the input points) and
    * sheet triangles given once per side (docs/design.md §8). See WrapResult::copies. */
  bool manifold = false;

  /** \brief Compute the wrap filtration: every simplex's value (in the kept complex) and
    * WrapResult::filtration, which gives X(delta) and W(delta) for any delta by a linear filter.
    * Costs the exact ordering of all sinks and one more retraction, and keeps the complex. */
  bool filtration = false;

};

} // namespace pcl_wrap
