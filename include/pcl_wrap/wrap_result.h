// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pcl_wrap
{

/** \brief Index of an input point (into the point array given to the construction, or, from the
  * PCL class, into the input cloud). */
using PointIndex = std::uint32_t;

/** \brief The three kinds of Delaunay simplices of the paper's §5 (docs/design.md §3). */
enum class SimplexClass : std::uint8_t
{
  centered,  ///< a sink: not attached, its smallest orthosphere's centre inside it
  confident, ///< not attached, centre outside it: flows on to its lowest successor
  equivocal  ///< attached: the flow passes through it, it has exactly one predecessor
};

/** \brief "centered", "confident" or "equivocal". */
const char*
toString (SimplexClass c);

/** \brief The simplices of one dimension of the Delaunay complex Del S. */
struct SimplexList
{
  /** \brief k+1 point indices per simplex; tetrahedra positively oriented, lower simplices in
    * ascending order. */
  std::vector<PointIndex> vertices;
  std::vector<SimplexClass> classes; ///< one per simplex
  std::vector<std::uint8_t> in_x;    ///< one per simplex: 1 when the simplex is in X
  /** \brief With WrapParameters::filtration, one per simplex: its wrap filtration value, the size
    * of the sink whose deletion removes it from X when every sink is deleted in order of
    * decreasing size (docs/design.md §6); +inf when the basic construction already removes it,
    * -inf when nothing does. It is in X(delta) iff value <= delta and value < +inf. */
  std::vector<double> values;

  std::size_t size () const { return classes.size (); }
};

/** \brief A surface in point indices: the output (WrapResult::surface), or the paper's W = Bd X
  * (docs/design.md §5). */
struct WrapSurface
{
  /** \brief Oriented triangles. The default surface's face away from its inside; W's are the
    * triangles of X with fewer than two tetrahedra of X behind them, facing away from the one
    * behind them (sheets: consistently per sheet). */
  std::vector<std::array<PointIndex, 3>> triangles;
  /** \brief W: the edges of X with no triangle of X on them, each with its smaller index first. */
  std::vector<std::array<PointIndex, 2>> dangling_edges;
  /** \brief W: the vertices of X with no edge of X on them. */
  std::vector<PointIndex> isolated_vertices;
};

/** \brief The wrap filtration (docs/design.md §6): one pass deleting every sink in order of
  * decreasing size gives each simplex the size at which it leaves X, so X(delta) and W(delta) = Bd
  * X(delta), the global deletion of every sink larger than delta, come out of a linear filter for
  * any delta without a new triangulation or retraction. Nested: X(d1) contains X(d2) for d1 > d2.
  * Shares the complex it was computed on; copies are cheap. */
class Filtration
{
public:
  struct Data;
  Filtration () = default;
  explicit Filtration (std::shared_ptr<const Data> data) : data_ (std::move (data)) {}

  /** \brief Was it computed (WrapParameters::filtration)? */
  bool empty () const { return !data_; }
  /** \brief The sizes (squared radii) of the sinks other than omega, decreasing: the values of
    * delta where X(delta) can change. */
  const std::vector<double>& sinkSizes () const;
  /** \brief The number of simplices of X(delta) per dimension. */
  std::array<std::size_t, 4> xSize (double delta) const;
  /** \brief W(delta) = Bd X(delta); delta = +inf gives the basic wrap. */
  WrapSurface surface (double delta) const;
  /** \brief The same filtration with every point index i read as \a index (i). */
  Filtration reindexed (const std::function<std::uint32_t (std::uint32_t)>& index) const;

private:
  std::shared_ptr<const Data> data_;
};

/** \brief Wall-clock seconds of one stage of the construction. */
struct StageTiming
{
  std::string stage;
  double seconds = 0.0;
};

/** \brief What the construction did, in numbers. */
struct WrapStatistics
{
  std::size_t points_input = 0;     ///< points given (after setIndices)
  std::size_t points_used = 0;      ///< vertices of the triangulation
  std::size_t points_skipped = 0;   ///< non-finite coordinates or weight
  std::size_t points_duplicate = 0; ///< same position as a kept point
  std::size_t points_hidden = 0;    ///< empty power cell (weighted input only)
  std::size_t points_apart = 0;     ///< the default surface: apart from all others, left off it
  std::size_t points_off_surface = 0; ///< used, and on no triangle of the output (WrapResult::off_surface)
  int triangulation_dimension = -1; ///< -1 (no point), 0, 1, 2 or 3

  /** \brief Simplices of Del S per dimension and class: [dimension][class]. */
  std::array<std::array<std::size_t, 3>, 4> simplices{};
  /** \brief Simplices of X per dimension. */
  std::array<std::size_t, 4> x_simplices{};
  std::size_t collapses = 0;        ///< collapses performed by the retraction
  std::size_t perturbations = 0;    ///< predicate ties decided by the symbolic perturbation

  /** \brief The median nearest-neighbour distance of the points used (0 below two points),
    * always. Sink deletion (when asked for): the threshold used (a squared radius), the largest
    * sink sizes, and what was deleted. */
  double spacing = 0.0;
  double delta = std::numeric_limits<double>::infinity ();
  std::vector<double> largest_sinks;
  std::size_t sinks = 0;              ///< sinks other than omega
  std::size_t sinks_deleted = 0;
  std::size_t sinks_enclosed = 0;     ///< front: larger than delta, principal, basin kept inside
  /** \brief Larger than delta, still in X and never principal. Global mode: the theory says
    * none. Front mode: the sinks below an enclosed one (its kept basin covers them, so they are
    * never uncovered), and with a region the sinks outside it. */
  std::size_t sinks_not_principal = 0;

  /** \brief With WrapParameters::manifold: the edges and vertices of W split, and the sheet
    * triangles doubled (one per side), to make the output a 2-manifold. */
  std::size_t pinch_edges_split = 0;
  std::size_t pinch_vertices_split = 0;
  std::size_t sheet_triangles_doubled = 0;

  /** \brief The default surface: tetrahedra moved across it to make it a 2-manifold through the
    * points. */
  std::size_t tetrahedra_moved = 0;
  /** \brief The default surface: the labelled solid's surface would have fewer points on it than
    * the paper's W (a coarse sample, where the labels seal a hole that W keeps open), so the output
    * is W, split into a closed 2-manifold as the raw output's WrapParameters::manifold splits it. */
  bool surface_is_w = false;
  /** \brief The default surface: the points are a single layer (a terrain, a scan seen from one
    * side), so the surface is one open sheet through them (Output::surface) or X's boundary as a
    * closed two-sided shell, the points copied per side (Output::closed). */
  bool single_layer = false;
  /** \brief With single_layer and Output::closed: Delaunay triangles and tetrahedra added to tie pieces of the shell
    * that the split separated at a vertex to the rest, or to bring on a point that X holds by a
    * dangling edge alone. */
  std::size_t bridge_simplices = 0;

  std::size_t w_triangles = 0;
  std::size_t w_dangling_edges = 0;
  std::size_t w_isolated_vertices = 0;

  /** \brief Seconds per stage, in the order they ran. */
  std::vector<StageTiming> timings;
  /** \brief Sum of the stage timings: points in memory to surface (or mesh) in memory. */
  double total_seconds = 0.0;
};

/** \brief Everything the construction produces. All indices are point indices. */
struct WrapResult
{
  WrapStatistics statistics;
  /** \brief The output (WrapParameters::output): the default surface, an oriented 2-manifold
    * through the points, closed, or open for a single layer (docs/surface.md), or the paper's W as
    * it is (Output::raw),
    * split into a 2-manifold with WrapParameters::manifold. */
  WrapSurface surface;
  /** \brief With WrapParameters::keep_complex: Del S by dimension with each simplex's class and
    * membership in X, and the paper's W = Bd X, whatever the output; empty otherwise. */
  std::array<SimplexList, 4> complex;
  WrapSurface w;
  std::vector<PointIndex> skipped;   ///< points with a non-finite coordinate or weight
  std::vector<PointIndex> hidden;    ///< points with an empty power cell
  /** \brief The default surface: points apart from all others (far outliers, alone or up to three
    * together: more than 16 median spacings from the rest, and most of their Delaunay neighbours
    * more than 16 times nearer their own nearest points), which it leaves off, where a closed
    * surface through them would be a spike (docs/surface.md, "Points apart"). */
  std::vector<PointIndex> apart;
  /** \brief Every point used (a vertex of Del S) that no triangle of \a surface has, itself or
    * as a copy, in ascending order: the points apart, points inside a volume, points a surface
    * leaves inside or outside its solid, and points on a dangling edge or isolated vertex of W
    * alone, which no mesh carries. Each point given is on a triangle of the surface or in exactly
    * one of off_surface, skipped, hidden and the duplicates' first indices. */
  std::vector<PointIndex> off_surface;
  /** \brief The points copied to split the output where it touches itself (the default surface,
    * or the raw output with WrapParameters::manifold). Point index n + k (n = the number of input points) in
    * surface.triangles is a copy of point copies[k]. */
  std::vector<PointIndex> copies;
  /** \brief With WrapParameters::filtration: X(delta) and W(delta) for any delta. */
  Filtration filtration;
  /** \brief (duplicate, kept point at the same position). */
  std::vector<std::pair<PointIndex, PointIndex>> duplicates;

  /** \brief The simplices of X of dimension k, k+1 point indices each (see SimplexList). */
  std::vector<PointIndex>
  xSimplices (int k) const;
};

} // namespace pcl_wrap
