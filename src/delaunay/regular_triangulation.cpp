// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/regular_triangulation.h"

#include "delaunay/address_index.h"
#include "delaunay/cgal_kernel.h"
#include "util/parallel_for_each.h"
#include "delaunay/z_order.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Spatial_lock_grid_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <tbb/scalable_allocator.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <optional>
#include <type_traits>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

// Vertex infos are point indices (cells are numbered by their addresses: AddressIndex). Each
// triangulation comes in two builds: Parallel_tag inserts on all threads, given a lock grid;
// Sequential_tag has lighter containers, about 10% faster on one thread.
using LockGrid = CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking>;
template <class Concurrency>
constexpr bool IS_PARALLEL = std::is_same_v<Concurrency, CGAL::Parallel_tag>;
template <class Concurrency>
using LockGridOf = std::conditional_t<IS_PARALLEL<Concurrency>, LockGrid, CGAL::Default>;

// Hidden points are found from the vertex set afterwards, so cells need not store them.
using RegularVertex = CGAL::Triangulation_vertex_base_with_info_3<
    std::uint32_t, Kernel, CGAL::Regular_triangulation_vertex_base_3<Kernel>>;
using RegularCell = CGAL::Regular_triangulation_cell_base_3<Kernel, CGAL::Triangulation_cell_base_3<Kernel>,
                                                            CGAL::Discard_hidden_points>;
template <class Concurrency>
using Regular = CGAL::Regular_triangulation_3<
    Kernel, CGAL::Triangulation_data_structure_3<RegularVertex, RegularCell, Concurrency>, LockGridOf<Concurrency>>;

// Equal weights shift every power distance alike: the regular triangulation is the Delaunay
// triangulation, and CGAL builds that about 15% faster. In dimension 3 both break cospherical
// ties by the same symbolic perturbation (points in lexicographic order, the largest lifted
// most), so they give the same tetrahedra; lower dimensions keep to Regular.
using DelaunayVertex = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using DelaunayCell = CGAL::Delaunay_triangulation_cell_base_3<Kernel>;
template <class Concurrency>
using Delaunay = CGAL::Delaunay_triangulation_3<
    Kernel, CGAL::Triangulation_data_structure_3<DelaunayVertex, DelaunayCell, Concurrency>, CGAL::Default,
    LockGridOf<Concurrency>>;

// Below this many points the threads would mostly wait on each other's locks.
constexpr std::size_t PARALLEL_INSERTION_MIN_POINTS = 20000;
// From this many points an observed insertion reports its progress, in this many rounds.
constexpr std::size_t PROGRESS_MIN_POINTS = 100000;
constexpr std::uint32_t PROGRESS_ROUNDS = 20;
// Lock grid cells per axis (CGAL's examples use 50; more cells, fewer conflicts).
constexpr int LOCK_GRID_CELLS = 50;

/** A triangulation's finite tetrahedra as read from CGAL, in CGAL's (thread-timing dependent)
  * order: each one's vertex ids in canonicalOrder, and across each of them the neighbour's
  * index in this order, or NO_NEIGHBOUR. */
struct CgalTetrahedra
{
  FilledInParallel<std::uint32_t> vertices, across;
};

template <class Cgal, class Id>
CgalTetrahedra
readTetrahedra (const Cgal& rt, const Id& id)
{
  // Cells are numbered first, by their addresses, so that the one pass over them finds their
  // neighbours' numbers without reading the neighbours.
  AddressIndex<sizeof (typename Cgal::Cell)> number;
  HugePageVector<typename Cgal::Cell_handle> cells;
  cells.reserve (rt.tds ().number_of_cells ());
  number.reserve (rt.tds ().number_of_cells ());
  for (auto c = rt.all_cells_begin (); c != rt.all_cells_end (); ++c)
    if (rt.is_infinite (c))
      number.add (&*c, NO_NEIGHBOUR);
    else
    {
      number.add (&*c, static_cast<std::uint32_t> (cells.size ()));
      cells.push_back (c);
    }
  number.seal ();
  CgalTetrahedra read;
  read.vertices.resize (4 * cells.size ());
  read.across.resize (4 * cells.size ());
  parallelForEach (cells.size (), [&] (std::size_t j) {
    std::uint32_t v[4];
    for (int i = 0; i < 4; ++i)
      v[i] = id (cells[j]->vertex (i));
    const std::array<int, 4> p = canonicalOrder (v);
    for (int i = 0; i < 4; ++i)
    {
      read.vertices[4 * j + i] = v[p[i]];
      read.across[4 * j + i] = number[&*cells[j]->neighbor (p[i])];
    }
  });
  return read;
}

/** The tetrahedra \a read into \a t, in tetrahedronOrder(). */
void
orderTetrahedra (const CgalTetrahedra& read, Triangulation& t)
{
  const std::size_t n = read.vertices.size () / 4;
  const FilledInParallel<std::uint32_t> order = tetrahedronOrder (read.vertices, t.point_of_vertex.size ());
  FilledInParallel<std::uint32_t> rank (n);
  parallelForEach (n, [&] (std::size_t r) { rank[order[r]] = static_cast<std::uint32_t> (r); });

  t.top_simplices.resize (4 * n);
  t.neighbours.resize (4 * n);
  parallelForEach (n, [&] (std::size_t r) {
    const std::size_t j = order[r];
    for (int i = 0; i < 4; ++i)
    {
      t.top_simplices[4 * r + i] = read.vertices[4 * j + i];
      const std::uint32_t u = read.across[4 * j + i];
      t.neighbours[4 * r + i] = u == NO_NEIGHBOUR ? NO_NEIGHBOUR : rank[u];
    }
  });
}

/** Whether the \a n distinct points \a point (i) span space, decided by exact orientation tests. */
template <class Point>
bool
spanSpace (std::size_t n, const Point& point)
{
  std::size_t i = 2;
  while (i < n && CGAL::collinear (point (0), point (1), point (i)))
    ++i;
  const std::size_t third = i;
  for (++i; i < n; ++i)
    if (CGAL::orientation (point (0), point (1), point (third), point (i)) != CGAL::COPLANAR)
      return true;
  return false;
}

/** Numbers the vertices of \a rt (whose infos are point indices) along a space-filling curve:
  * neighbours in space are neighbours in every array indexed by vertex (and so by edge and
  * triangle), which keeps the later stages in cache. The numbering depends only on the points,
  * never on CGAL's internals. Fills \a t's dimension, point_of_vertex and hidden; returns the
  * vertex id of each point (~0 for a hidden one). */
template <class Cgal>
std::vector<std::uint32_t>
numberVertices (const Cgal& rt, const std::vector<Point3>& positions, Triangulation& t)
{
  t.dimension = rt.number_of_vertices () == 0 ? -1 : rt.dimension ();
  const std::vector<std::uint32_t> curve = zOrder (positions);
  constexpr std::uint32_t ABSENT = ~std::uint32_t (0);
  std::vector<std::uint32_t> vertex_of_point (positions.size (), ABSENT);
  for (auto v = rt.finite_vertices_begin (); v != rt.finite_vertices_end (); ++v)
    vertex_of_point[v->info ()] = 0;
  for (std::uint32_t i : curve)
    if (vertex_of_point[i] != ABSENT)
    {
      vertex_of_point[i] = static_cast<std::uint32_t> (t.point_of_vertex.size ());
      t.point_of_vertex.push_back (i);
    }
  for (std::uint32_t i = 0; i < positions.size (); ++i)
    if (vertex_of_point[i] == ABSENT)
      t.hidden.push_back (i);
  return vertex_of_point;
}

/** Reads \a rt's top simplices into \a t in vertex ids (\a id of a vertex handle), calling
  * \a release once CGAL's cells are no longer needed. */
template <class Cgal, class Id, class Release>
void
readTopSimplices (const Cgal& rt, const Id& id, Triangulation& t, const Release& release)
{
  auto& top = t.top_simplices;
  switch (t.dimension)
  {
  case 3:
  {
    const CgalTetrahedra read = readTetrahedra (rt, id);
    release ();
    orderTetrahedra (read, t);
    return;
  }
  case 2:
  {
    // Each triangle from its lowest vertex on (a rotation, as CGAL oriented it), listed by its
    // vertex set: an order that CGAL's cells and the order of insertion do not change.
    std::vector<std::array<std::uint32_t, 3>> triangles;
    for (auto f = rt.finite_facets_begin (); f != rt.finite_facets_end (); ++f)
    {
      std::array<std::uint32_t, 3> v{id (f->first->vertex (0)), id (f->first->vertex (1)), id (f->first->vertex (2))};
      std::rotate (v.begin (), std::min_element (v.begin (), v.end ()), v.end ());
      triangles.push_back (v);
    }
    const auto key = [] (const std::array<std::uint32_t, 3>& v) {
      return std::array<std::uint32_t, 3>{v[0], std::min (v[1], v[2]), std::max (v[1], v[2])};
    };
    std::sort (triangles.begin (), triangles.end (), [&] (const auto& a, const auto& b) { return key (a) < key (b); });
    for (const auto& v : triangles)
      top.insert (top.end (), v.begin (), v.end ());
    break;
  }
  case 1:
  {
    std::vector<std::array<std::uint32_t, 2>> edges;
    for (auto e = rt.finite_edges_begin (); e != rt.finite_edges_end (); ++e)
    {
      const std::uint32_t a = id (e->first->vertex (e->second)), b = id (e->first->vertex (e->third));
      edges.push_back ({std::min (a, b), std::max (a, b)});
    }
    std::sort (edges.begin (), edges.end ());
    for (const auto& v : edges)
      top.insert (top.end (), v.begin (), v.end ());
    break;
  }
  case 0:
    top.push_back (0);
    break;
  default:
    break;
  }
  release ();
}

/** The triangulation of the points by CGAL's \a Cgal, whose sites \a site makes from point
  * indices. */
template <class Cgal, class Site>
Triangulation
triangulateWith (const std::vector<Point3>& positions, const Site& site, const std::function<void (double)>& progress)
{
  std::vector<std::pair<typename Cgal::Point, std::uint32_t>> input;
  input.reserve (positions.size ());
  CGAL::Bbox_3 box;
  for (std::uint32_t i = 0; i < positions.size (); ++i)
  {
    input.emplace_back (site (i), i);
    box += input.back ().first.bbox ();
  }
  Cgal rt;
  std::optional<LockGrid> locks;
  if constexpr (IS_PARALLEL<typename Cgal::Concurrency_tag>)
  {
    locks.emplace (box, LOCK_GRID_CELLS);
    rt.set_lock_data_structure (&*locks);
  }
  if (!progress || input.size () < PROGRESS_MIN_POINTS)
    rt.insert (input.begin (), input.end ()); // spatially sorted insertion
  else
  {
    // Rounds of consecutive stretches of one space-filling curve through the points: each
    // round grows the triangulation by a region, whose cells stay near each other in memory as
    // they do in one insertion. (Rounds of random samples would spread each round's new cells
    // over the whole triangulation: about 1.8 times as long at a million points.)
    std::vector<std::pair<typename Cgal::Point, std::uint32_t>> along;
    along.reserve (input.size ());
    for (std::uint32_t i : zOrder (positions))
      along.push_back (std::move (input[i]));
    input = std::move (along);
    for (std::uint32_t r = 0; r < PROGRESS_ROUNDS; ++r)
    {
      rt.insert (input.begin () + r * input.size () / PROGRESS_ROUNDS,
                 input.begin () + (r + 1) * input.size () / PROGRESS_ROUNDS);
      progress (double (r + 1) / PROGRESS_ROUNDS);
    }
  }
  input = {};
  rt.set_lock_data_structure (nullptr);

  Triangulation t;
  const std::vector<std::uint32_t> vertex_of_point = numberVertices (rt, positions, t);
  // From here on a vertex's info is its id (one indirection less per lookup).
  for (auto v = rt.finite_vertices_begin (); v != rt.finite_vertices_end (); ++v)
    v->info () = vertex_of_point[v->info ()];
  // CGAL's triangulation is let go as soon as it has been read: ordering the tetrahedra takes
  // a few hundred megabytes more at a million points. Its parallel build allocates through TBB's
  // allocator, which keeps freed memory for reuse; that is given back too. (Only then: asked
  // before it ever allocated, the allocator crashes.)
  readTopSimplices (
      rt, [] (typename Cgal::Vertex_handle v) { return v->info (); }, t,
      [&rt] {
        rt.clear ();
        if constexpr (IS_PARALLEL<typename Cgal::Concurrency_tag>)
          scalable_allocation_command (TBBMALLOC_CLEAN_ALL_BUFFERS, nullptr);
      });
  return t;
}

/** A triangulation kept between batches of points (GrowingTriangulation). */
template <class Cgal>
class Growing : public GrowingTriangulation::State
{
public:
  void insert (const std::vector<Point3>& positions, const std::vector<double>& weights, std::size_t first) override
  {
    std::vector<std::pair<typename Cgal::Point, std::uint32_t>> input;
    input.reserve (positions.size () - first);
    CGAL::Bbox_3 box;
    for (std::size_t i = first; i < positions.size (); ++i)
    {
      input.emplace_back (site (positions[i], weights[i]), static_cast<std::uint32_t> (i));
      box += input.back ().first.bbox ();
    }
    // The lock grid spans the first batch; later points beyond it lock its border cells.
    if constexpr (IS_PARALLEL<typename Cgal::Concurrency_tag>)
      if (!locks_)
      {
        locks_.emplace (box, LOCK_GRID_CELLS);
        rt_.set_lock_data_structure (&*locks_);
      }
    rt_.insert (input.begin (), input.end ()); // spatially sorted insertion
  }

  Triangulation read (const std::vector<Point3>& positions) const override
  {
    Triangulation t;
    const std::vector<std::uint32_t> vertex_of_point = numberVertices (rt_, positions, t);
    readTopSimplices (
        rt_, [&] (typename Cgal::Vertex_handle v) { return vertex_of_point[v->info ()]; }, t, [] {});
    return t;
  }

  std::vector<std::array<std::uint32_t, 2>> edges () const override
  {
    std::vector<std::array<std::uint32_t, 2>> out;
    out.reserve (rt_.number_of_finite_edges ());
    for (auto e = rt_.finite_edges_begin (); e != rt_.finite_edges_end (); ++e)
    {
      const std::uint32_t a = e->first->vertex (e->second)->info (), b = e->first->vertex (e->third)->info ();
      out.push_back ({std::min (a, b), std::max (a, b)});
    }
    return out;
  }

private:
  static typename Cgal::Point site (const Point3& p, double w)
  {
    const BarePoint bare (p[0], p[1], p[2]);
    if constexpr (std::is_same_v<typename Cgal::Point, WeightedPoint>)
      return WeightedPoint (bare, w);
    else
      return bare;
  }

  std::optional<LockGrid> locks_; // declared before rt_, which points to it: destroyed after
  Cgal rt_;
};

} // namespace

std::array<int, 4>
canonicalOrder (const std::uint32_t* v)
{
  std::array<int, 4> p = {0, 1, 2, 3};
  const int low = static_cast<int> (std::min_element (v, v + 4) - v);
  // The even permutations that move `low` to the front: swap it with 0, and two other slots.
  if (low != 0)
  {
    std::swap (p[0], p[low]);
    const int a = low == 1 ? 2 : 1, b = low == 3 ? 2 : 3;
    std::swap (p[a], p[b]);
  }
  // Rotate the last three (an even permutation) until the smallest of them is second.
  while (v[p[1]] > v[p[2]] || v[p[1]] > v[p[3]])
    std::rotate (p.begin () + 1, p.begin () + 2, p.end ());
  return p;
}

FilledInParallel<std::uint32_t>
tetrahedronOrder (const FilledInParallel<std::uint32_t>& vertices, std::size_t num_vertices)
{
  // Bucket by lowest vertex, then sort each bucket by the other three (as a set).
  // The key travels with the tetrahedron, so that sorting a bucket reads nothing else.
  struct Keyed
  {
    std::array<std::uint32_t, 3> key; // the other three vertices, as a set
    std::uint32_t tetrahedron;
    bool operator<(const Keyed& o) const { return key < o.key; }
  };
  const std::size_t n = vertices.size () / 4;
  std::vector<std::size_t> begin;
  const auto keyed = bucketInParallel<Keyed> (
      n, num_vertices,
      [&] (std::size_t j, auto put) {
        const std::uint32_t* v = &vertices[4 * j];
        put (v[0], Keyed{{v[1], std::min (v[2], v[3]), std::max (v[2], v[3])}, static_cast<std::uint32_t> (j)});
      },
      begin, [] (std::size_t, auto first, auto last) { std::sort (first, last); });
  FilledInParallel<std::uint32_t> order (n);
  parallelForEach (n, [&] (std::size_t r) { order[r] = keyed[r].tetrahedron; });
  return order;
}

GrowingTriangulation::GrowingTriangulation (bool equal_weights) : equal_weights_ (equal_weights) {}

GrowingTriangulation::~GrowingTriangulation () = default;

void
GrowingTriangulation::insert (const std::vector<Point3>& positions, const std::vector<double>& weights,
                              std::size_t first)
{
  if (!state_)
  {
    // Threads when the first batch is large enough for them, as in triangulate().
    const bool parallel =
        positions.size () - first >= PARALLEL_INSERTION_MIN_POINTS && tbb::this_task_arena::max_concurrency () > 1;
    if (equal_weights_)
      state_ = parallel ? std::unique_ptr<State> (new Growing<Delaunay<CGAL::Parallel_tag>> ())
                        : std::unique_ptr<State> (new Growing<Delaunay<CGAL::Sequential_tag>> ());
    else
      state_ = parallel ? std::unique_ptr<State> (new Growing<Regular<CGAL::Parallel_tag>> ())
                        : std::unique_ptr<State> (new Growing<Regular<CGAL::Sequential_tag>> ());
  }
  state_->insert (positions, weights, first);
}

Triangulation
GrowingTriangulation::read (const std::vector<Point3>& positions) const
{
  if (!state_)
    return {};
  return state_->read (positions);
}

std::vector<std::array<std::uint32_t, 2>>
GrowingTriangulation::edges () const
{
  if (!state_)
    return {};
  return state_->edges ();
}

Triangulation
triangulate (const std::vector<Point3>& positions, const std::vector<double>& weights,
             const std::function<void (double)>& progress)
{
  const auto point = [&] (std::uint32_t i) {
    return BarePoint (positions[i][0], positions[i][1], positions[i][2]);
  };
  const auto weighted = [&] (std::uint32_t i) { return WeightedPoint (point (i), weights[i]); };
  const bool equal_weights = std::all_of (weights.begin (), weights.end (), [&] (double w) { return w == weights[0]; });
  const bool delaunay = equal_weights && spanSpace (positions.size (), point);
  const bool parallel = positions.size () >= PARALLEL_INSERTION_MIN_POINTS &&
                        tbb::this_task_arena::max_concurrency () > 1;
  Triangulation t = delaunay   ? parallel ? triangulateWith<Delaunay<CGAL::Parallel_tag>> (positions, point, progress)
                                          : triangulateWith<Delaunay<CGAL::Sequential_tag>> (positions, point, progress)
                      : parallel ? triangulateWith<Regular<CGAL::Parallel_tag>> (positions, weighted, progress)
                               : triangulateWith<Regular<CGAL::Sequential_tag>> (positions, weighted, progress);
  return t;
}

} // namespace pcl_wrap::detail
