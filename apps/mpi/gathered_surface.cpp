// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "gathered_surface.h"

#include "delaunay/input_points.h"
#include "delaunay/power_predicates.h"
#include "delaunay/regular_triangulation.h"
#include "delaunay/tetrahedra.h"
#include "delaunay/z_order.h"
#include "filtration_data.h"
#include "input_indices.h"
#include "surface/default_surface.h"
#include "surface/solid_labelling.h"
#include "util/parallel_for_each.h"
#include "wrap_engine.h"
#include "wrap/boundary.h"
#include "wrap/classification.h"
#include "wrap/sink_deletion.h"
#include "wrap/wrap_filtration.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

namespace pcl_wrap::mpi
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

/** Per tetrahedron of \a top, the tetrahedron across the facet opposite each local vertex, or
  * NO_NEIGHBOUR on the hull: the facets bucketed by their lowest vertex, and matched in each
  * bucket by their other two. */
detail::FilledInParallel<std::uint32_t>
neighboursOf (const detail::FilledInParallel<std::uint32_t>& top, std::size_t num_vertices)
{
  struct Facet
  {
    std::array<std::uint32_t, 2> rest; // its other two vertices, ascending
    std::uint32_t slot;                // 4 t + i
    bool operator<(const Facet& o) const { return rest < o.rest; }
  };
  detail::FilledInParallel<std::uint32_t> across (top.size (), detail::NO_NEIGHBOUR);
  std::vector<std::size_t> begin;
  detail::bucketInParallel<Facet> (
      top.size (), num_vertices,
      [&] (std::size_t slot, auto put) {
        const std::size_t t = slot / 4, i = slot % 4;
        std::array<std::uint32_t, 3> f{top[4 * t + (i + 1) % 4], top[4 * t + (i + 2) % 4], top[4 * t + (i + 3) % 4]};
        std::sort (f.begin (), f.end ());
        put (f[0], Facet{{f[1], f[2]}, static_cast<std::uint32_t> (slot)});
      },
      begin,
      [&] (std::size_t, auto first, auto last) {
        std::sort (first, last);
        for (auto f = first; f != last && f + 1 != last; ++f)
          if (f->rest == (f + 1)->rest)
          {
            across[f->slot] = (f + 1)->slot / 4;
            across[(f + 1)->slot] = f->slot / 4;
          }
      });
  return across;
}

/** Flags, in \a members, the simplex with the vertex ids \a v (\a n of them) and its faces. */
void
flagWithFaces (const detail::Tetrahedra& tetrahedra, const std::uint32_t* v, int n, detail::Star& star,
               std::array<std::vector<std::uint8_t>, 4>& members)
{
  const auto [t, mask] = tetrahedra.faceAround (v[0], v, n, star);
  if (t == detail::NO_TETRAHEDRON)
    return;
  for (unsigned sub = mask; sub != 0; sub = (sub - 1) & mask)
  {
    const detail::Simplex f = tetrahedra.complex ().face (3, t, sub);
    members[f.dim][f.id] = 1;
  }
}

/** Sets WrapResult::complex of \a result as one process sets it: X with every simplex's class,
  * and with \a filtration the wrap filtration (each simplex's value, the sink counts). The
  * classes are found again on the gathered complex, from the same predicates. */
void
keepComplex (const std::shared_ptr<const detail::SimplicialComplex>& complex, const std::vector<Point3>& positions,
             const std::vector<double>& weights, const detail::Subcomplex& x, const detail::InputIndices& indices,
             bool filtration, WrapResult& result)
{
  const detail::PowerPredicates predicates (positions, weights);
  const auto classification = std::make_shared<const detail::Classification> (detail::classify (*complex, predicates));
  result.complex = indices.complex (*complex, *classification, x);
  if (!filtration)
    return;
  const auto values = std::make_shared<const detail::WrapFiltration> (
      detail::wrapFiltration (*complex, *classification, positions, weights));
  for (int k = 0; k <= 3; ++k)
    result.complex[k].values = values->value[k];
  result.filtration = Filtration (
      std::make_shared<const Filtration::Data> (Filtration::Data{complex, classification, values, indices}));
  detail::recordSinks (*values, result.statistics);
}

} // namespace

TileSolid
tileSolid (const TileComplex& tile, const detail::Subcomplex& y)
{
  const detail::SimplicialComplex& complex = tile.complex ();
  TileSolid out;
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    if (tile.belongsHere ({3, t}))
    {
      const std::uint32_t* v = complex.vertices (3, t);
      out.tetrahedra.push_back ({tile.indexOf (v[0]), tile.indexOf (v[1]), tile.indexOf (v[2]), tile.indexOf (v[3])});
      out.in_x.push_back (y.contains ({3, t}));
    }
  return out;
}

void
surfaceOnRoot (const apps::PointFile& file, const std::vector<PointIndex>& hidden, TileSolid solid,
               const std::vector<std::array<std::uint32_t, 3>>& sheets, const WrapSurface& raw_w,
               const WrapParameters& parameters, WrapResult& result, detail::StageClock& clock)
{
  // The points and vertex ids of one process: S selected from the file, then the vertices (the
  // points not hidden) numbered along the Z-order curve of S.
  std::vector<std::uint32_t> vertex_of_index (file.points.size (), NONE);
  std::vector<Point3> positions;
  std::vector<double> weights;
  std::vector<PointIndex> input_of_vertex;
  {
    const detail::InputPoints input = detail::selectInputPoints (file.points, file.weights);
    positions.reserve (input.positions.size ());
    weights.reserve (input.positions.size ());
    input_of_vertex.reserve (input.positions.size ());
    std::vector<std::uint8_t> is_hidden (file.points.size (), 0);
    for (PointIndex h : hidden)
      is_hidden[h] = 1;
    for (std::uint32_t p : detail::zOrder (input.positions))
      if (!is_hidden[input.input_index[p]])
      {
        vertex_of_index[input.input_index[p]] = static_cast<std::uint32_t> (positions.size ());
        positions.push_back (input.positions[p]);
        weights.push_back (input.weights[p]);
        input_of_vertex.push_back (input.input_index[p]);
      }
  } // S is needed no more: freed before the complex is built
  const auto vertex = [&] (std::uint32_t index) {
    if (index >= vertex_of_index.size () || vertex_of_index[index] == NONE)
      throw std::runtime_error ("a tile sent a simplex on a point that is not a vertex");
    return vertex_of_index[index];
  };

  // The tetrahedra in triangulate()'s order: each in its canonical permutation, sorted by
  // vertex set.
  const std::size_t n = solid.tetrahedra.size ();
  detail::FilledInParallel<std::uint32_t> canon (4 * n);
  detail::parallelForEach (n, [&] (std::size_t t) {
    const auto& s = solid.tetrahedra[t];
    const std::uint32_t v[4] = {vertex (s[0]), vertex (s[1]), vertex (s[2]), vertex (s[3])};
    const std::array<int, 4> p = detail::canonicalOrder (v);
    for (int i = 0; i < 4; ++i)
      canon[4 * t + i] = v[p[i]];
  });
  const detail::FilledInParallel<std::uint32_t> order = detail::tetrahedronOrder (canon, positions.size ());
  detail::FilledInParallel<std::uint32_t> top (4 * n);
  std::vector<std::uint8_t> x_tetrahedra (n);
  detail::parallelForEach (n, [&] (std::size_t r) {
    const std::uint32_t t = order[r];
    std::copy (&canon[4 * t], &canon[4 * t] + 4, &top[4 * r]);
    x_tetrahedra[r] = solid.in_x[t];
  });
  solid = {};
  canon = {};
  detail::Tetrahedra adjacency (neighboursOf (top, positions.size ()));
  clock.stageDone ("tetrahedra");
  // As in one process: the votes before the complex takes its memory, the flood beside its build.
  std::optional<detail::DefaultSurface> stage;
  if (parameters.output != Output::raw)
  {
    const bool label_now = detail::labelAtOnce (parameters.output, positions, weights, clock);
    stage.emplace (top, adjacency, positions, weights, label_now);
    if (label_now)
      clock.stageDone ("votes");
  }
  const auto shared_complex =
      std::make_shared<const detail::SimplicialComplex> (3, static_cast<std::uint32_t> (positions.size ()),
                                                         std::move (top), adjacency.neighbourArray ());
  const detail::SimplicialComplex& complex = *shared_complex;
  adjacency.attach (complex);

  // X: the closure of its tetrahedra and of W's simplices on none of them.
  std::array<std::vector<std::uint8_t>, 4> members = detail::solidSubcomplex (complex, x_tetrahedra);
  detail::Star star;
  for (const auto& s : sheets)
  {
    const std::uint32_t v[3] = {vertex (s[0]), vertex (s[1]), vertex (s[2])};
    flagWithFaces (adjacency, v, 3, star, members);
  }
  for (const auto& e : raw_w.dangling_edges)
  {
    const std::uint32_t v[2] = {vertex (e[0]), vertex (e[1])};
    flagWithFaces (adjacency, v, 2, star, members);
  }
  for (PointIndex i : raw_w.isolated_vertices)
    members[0][vertex (i)] = 1;
  detail::Subcomplex x (complex, members);
  members = {};
  clock.stageDone ("complex");
  detail::InputIndices indices (std::move (input_of_vertex));
  WrapStatistics& stats = result.statistics;
  if (parameters.keep_complex)
  {
    keepComplex (shared_complex, positions, weights, x, indices, parameters.filtration, result);
    clock.stageDone ("filtration");
  }
  if (parameters.threshold.deletes ())
  {
    // The sink deletion of one process (design.md §6) on the same complex and X, the classes
    // found again from the same predicates.
    const detail::PowerPredicates predicates (positions, weights);
    const detail::Classification classification = detail::classify (complex, predicates);
    detail::deleteSinks (complex, classification, positions, weights, parameters, nullptr, x, stats);
    for (int k = 0; k <= 3; ++k)
      stats.x_simplices[k] = x.size (k);
    clock.stageDone ("deletion");
  }
  if (parameters.output == Output::raw)
  {
    result.surface =
        indices.surface (detail::extractBoundary (complex, x, true, [&] (std::uint32_t v) { return indices (v); }));
    clock.stageDone ("output");
    return;
  }

  detail::DefaultSurface::Output out = stage->surface (
      x, positions, false, file.viewpoint,
      [&] (std::size_t stride) { return detail::sampleIsSingleLayer (positions, weights, stride); },
      [&] (std::uint32_t v) { return indices (v); }, result.statistics, clock);
  if (out.split)
    indices.takeSplit (*out.split, out.w, file.points.size (), result);
  result.surface = indices.surface (out.w);
  result.apart = indices.sortedPoints (out.apart);
  result.statistics.points_apart = result.apart.size ();
  clock.stageDone ("output");
}

void
recordPointsOff (std::size_t input_points, WrapResult& result)
{
  std::vector<std::uint8_t> used (input_points, 1);
  for (PointIndex p : result.skipped)
    used[p] = 0;
  for (const auto& d : result.duplicates)
    used[d.first] = 0;
  for (PointIndex p : result.hidden)
    used[p] = 0;
  std::vector<PointIndex> points;
  for (PointIndex p = 0; p < input_points; ++p)
    if (used[p])
      points.push_back (p);
  detail::InputIndices (std::move (points)).recordPointsOff (result, input_points);
}

} // namespace pcl_wrap::mpi
