// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The wrap filtration (docs/design.md §6): sinks deleted by decreasing size, each deletion followed
// by a retraction, one value per simplex; X(delta) for any delta by a filter.
#include "support/flow_checks.h"
#include "support/naive_retraction.h"
#include "support/pipeline.h"
#include "support/degenerate_samples.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include "wrap/wrap_filtration.h"

#include <pcl_wrap/compute_wrap.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace pcl_wrap::test
{
namespace
{

using detail::Simplex;
using detail::SimplexId;

detail::WrapFiltration
filtrationOf (const Pipeline& p, std::uint64_t order_seed = 0)
{
  return detail::wrapFiltration (p.complex, p.classification, p.points, p.weights, order_seed);
}

/** X(delta) as sorted tuples. */
std::vector<Tuple>
xAt (const Pipeline& p, const detail::WrapFiltration& f, double delta)
{
  std::vector<Tuple> x;
  forEachSimplex (p, [&] (Simplex s) {
    if (f.inX (s, delta))
      x.push_back (p.tuple (s));
  });
  std::sort (x.begin (), x.end ());
  return x;
}

std::vector<std::vector<Point3>>
samples (std::size_t n, unsigned seed)
{
  return {cubeSample (n, seed), sphereSample (n, seed, 0.05), torusSample (n, seed)};
}

TEST (WrapFiltration, ReproducesDeletionsOneByOne)
{
  for (unsigned seed = 1; seed <= 2; ++seed)
    for (const auto& points : samples (250, seed))
    {
      const Pipeline p (points);
      const auto f = filtrationOf (p);
      ASSERT_FALSE (f.sinks.empty ());
      // Delete the sinks one by one, independently, and compare after j deletions wherever the
      // j-th and (j+1)-th sizes differ (so a threshold separates them).
      detail::Subcomplex y (p.complex);
      detail::Retraction retraction (y, p.classification);
      retraction.retract ();
      EXPECT_EQ (xAt (p, f, std::numeric_limits<double>::max ()), p.retractedX ()) << "X(inf) is the basic X";
      std::size_t compared = 0;
      for (std::size_t j = 0; j < f.sinks.size (); ++j)
      {
        if (retraction.deletePrincipal (f.sinks[j]))
          retraction.retractFreed ();
        const double next = j + 1 < f.sinks.size () ? f.sink_sizes[j + 1] : -std::numeric_limits<double>::max ();
        if (!(next < f.sink_sizes[j]) || j % 7 != 0)
          continue;
        std::vector<Tuple> expected;
        forEachSimplex (p, [&] (Simplex s) {
          if (y.contains (s))
            expected.push_back (p.tuple (s));
        });
        std::sort (expected.begin (), expected.end ());
        ASSERT_EQ (xAt (p, f, next), expected) << "after " << j + 1 << " deletions";
        ++compared;
      }
      EXPECT_GT (compared, 5u);
    }
}

TEST (WrapFiltration, EqualsNaiveDeletionsOnExactClasses)
{
  std::size_t compared = 0;
  for (unsigned seed = 1; seed <= 3; ++seed)
    for (const auto& points : samples (30, seed))
    {
      const Pipeline p (points);
      const auto f = filtrationOf (p);
      const auto del = naiveComplexWithExactClasses (p);
      std::vector<Tuple> deletions;
      for (std::size_t j = 0; j < f.sinks.size (); ++j)
      {
        deletions.push_back (p.tuple (f.sinks[j]));
        const double next = j + 1 < f.sinks.size () ? f.sink_sizes[j + 1] : -std::numeric_limits<double>::max ();
        if (!(next < f.sink_sizes[j]) || (j > 3 && j % 5 != 0))
          continue;
        ASSERT_EQ (xAt (p, f, next), naiveRetraction (del, seed, deletions)) << "after deleting " << j + 1 << " sinks";
        ++compared;
      }
    }
  EXPECT_GT (compared, 20u);
}

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

/** The sinks of \a p by decreasing exact size, from CGAL's exact constructions (not the engine's
  * fractions), equal sizes by the sorted coordinates of their vertices; their sizes in \a sizes. */
std::vector<Simplex>
sinksInExactOrder (const Pipeline& p, std::vector<ExactKernel::FT>& sizes)
{
  using K = ExactKernel;
  const K::Compute_squared_radius_smallest_orthogonal_sphere_3 radius;
  struct Sink
  {
    Simplex s;
    K::FT size;
    std::vector<Point3> corners;
  };
  std::vector<Sink> sinks;
  forEachSimplex (p, [&] (Simplex s) {
    if (p.classification.of (s) != SimplexClass::centered)
      return;
    std::vector<K::Weighted_point_3> w;
    Sink sink{s, 0, {}};
    for (int i = 0; i <= s.dim; ++i)
    {
      const std::uint32_t v = p.complex.vertex (s.dim, s.id, i);
      w.emplace_back (K::Point_3 (p.points[v][0], p.points[v][1], p.points[v][2]), p.weights[v]);
      sink.corners.push_back (p.points[v]);
    }
    sink.size = s.dim == 0   ? radius (w[0])
                : s.dim == 1 ? radius (w[0], w[1])
                : s.dim == 2 ? radius (w[0], w[1], w[2])
                             : radius (w[0], w[1], w[2], w[3]);
    std::sort (sink.corners.begin (), sink.corners.end ());
    sinks.push_back (sink);
  });
  std::sort (sinks.begin (), sinks.end (), [] (const Sink& a, const Sink& b) {
    if (a.size != b.size)
      return a.size > b.size;
    return std::lexicographical_compare (a.corners.begin (), a.corners.end (), b.corners.begin (), b.corners.end ());
  });
  std::vector<Simplex> out;
  sizes.clear ();
  for (const Sink& sink : sinks)
  {
    out.push_back (sink.s);
    sizes.push_back (sink.size);
  }
  return out;
}

TEST (WrapFiltration, SinksAreInExactOrderAndAnyPrefixIsThePrefixOfTheWholeOrder)
{
  // The torus's tube holds many sinks of size 0.4^2 up to rounding, the grid many of exactly equal
  // sizes, the weighted cube sinks of every dimension: the order cannot come from doubles.
  const std::vector<Point3> grid = gridSample (5, 5, 4);
  const auto cube = cubeSample (400, 3);
  std::vector<double> weights;
  for (std::size_t i = 0; i < cube.size (); ++i)
    weights.push_back (0.002 * double (i % 7));
  const Pipeline torus (torusSample (3000, 4)), lattice (grid), weighted (cube, weights);
  for (const Pipeline* p : {&torus, &lattice, &weighted})
  {
    detail::WrapFiltration all;
    detail::orderSinks (p->complex, p->classification, p->points, p->weights, all);
    std::vector<ExactKernel::FT> sizes;
    const std::vector<Simplex> expected = sinksInExactOrder (*p, sizes);
    ASSERT_EQ (all.sinks.size (), expected.size ());
    EXPECT_EQ (all.sink_count, expected.size ());
    for (std::size_t j = 0; j < expected.size (); ++j)
      ASSERT_TRUE (all.sinks[j].dim == expected[j].dim && all.sinks[j].id == expected[j].id) << "rank " << j;
    // Prefixes: above a size (one of the sizes, so ties straddle it), or at least a count.
    for (const std::size_t j : {std::size_t (0), expected.size () / 3, expected.size () - 1})
      for (const std::size_t at_least : {std::size_t (0), std::size_t (10), expected.size () / 2})
      {
        const double delta = all.sink_sizes[j];
        detail::WrapFiltration prefix;
        detail::orderSinks (p->complex, p->classification, p->points, p->weights, prefix, delta, at_least);
        std::size_t length = 0;
        while (length < sizes.size () && (length < at_least || sizes[length] > delta))
          ++length;
        ASSERT_EQ (prefix.sinks.size (), length) << "delta " << delta << " at least " << at_least;
        EXPECT_EQ (prefix.sink_count, all.sink_count);
        for (std::size_t i = 0; i < length; ++i)
          ASSERT_TRUE (prefix.sinks[i].dim == all.sinks[i].dim && prefix.sinks[i].id == all.sinks[i].id);
      }
  }
}

TEST (WrapFiltration, EverySinkIsPrincipalAtItsTurnAndOrderDoesNotMatter)
{
  for (unsigned seed = 1; seed <= 3; ++seed)
    for (const auto& points : samples (1500, seed))
    {
      const Pipeline p (points);
      const auto f = filtrationOf (p);
      EXPECT_EQ (f.not_principal, 0u);
      EXPECT_GT (f.deletions, 0u);
      for (std::uint64_t order : {1u, 2u})
        EXPECT_EQ (filtrationOf (p, order).value, f.value);
    }
}

TEST (WrapFiltration, AFaceNeverLeavesBeforeItsCofacesSoEveryXIsAComplex)
{
  for (const auto& points : samples (1000, 4))
  {
    const Pipeline p (points);
    const auto f = filtrationOf (p);
    forEachSimplex (p, [&] (Simplex s) {
      for (unsigned mask = 1; mask < detail::fullMask (s.dim); ++mask)
      {
        const Simplex face = p.complex.face (s.dim, s.id, mask);
        ASSERT_LE (f.value[face.dim][face.id], f.value[s.dim][s.id]);
      }
    });
    // Nested: X(d1) contains X(d2) for d1 > d2.
    const auto a = xAt (p, f, f.sink_sizes[f.sink_sizes.size () / 4]);
    const auto b = xAt (p, f, f.sink_sizes[f.sink_sizes.size () / 2]);
    EXPECT_TRUE (std::includes (a.begin (), a.end (), b.begin (), b.end ()));
    EXPECT_TRUE (closedUnderFaces (a));
  }
}

/** Deleting the few largest sinks of a torus (those in its hole) opens the tunnel: X becomes a
  * solid torus, homotopic to a circle, and no longer meets the tunnel's axis. */
TEST (WrapFiltration, DeletingTheLargestSinksOpensTheTorusTunnel)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::size_t opened = 0;
  for (unsigned seed = 1; seed <= 4; ++seed)
  {
    const auto points = torusSample (200, seed);
    const Pipeline p (points);
    const auto f = filtrationOf (p);
    for (std::size_t j = 1; j <= 6 && j < f.sinks.size (); ++j)
    {
      if (!(f.sink_sizes[j] < f.sink_sizes[j - 1]))
        continue;
      const auto x = xAt (p, f, f.sink_sizes[j]);
      const Homology h = homology (x);
      if (h.components != 1 || h.euler != 0 || h.betti1 != 1)
        continue;
      const K::Segment_3 axis (K::Point_3 (0, 0, -0.4), K::Point_3 (0, 0, 0.4));
      const auto point = [&] (std::uint32_t v) { return K::Point_3 (p.points[v][0], p.points[v][1], p.points[v][2]); };
      bool meets = false;
      for (const auto& t : x)
        if (t.size () == 3)
          meets |= CGAL::do_intersect (axis, K::Triangle_3 (point (t[0]), point (t[1]), point (t[2])));
      EXPECT_FALSE (meets) << "seed " << seed << ": a solid torus that still spans the tunnel";
      ++opened;
      break;
    }
  }
  EXPECT_GE (opened, 3u) << "deleting at most 6 sinks should open most tori";
}

/** W's triangles, each rotated to start at its smallest index (orientation kept), sorted. */
std::vector<std::array<PointIndex, 3>>
canonical (const WrapSurface& w)
{
  auto t = w.triangles;
  for (auto& a : t)
    std::rotate (a.begin (), std::min_element (a.begin (), a.end ()), a.end ());
  std::sort (t.begin (), t.end ());
  return t;
}

/** The public filtration: W(delta) from one computation equals a global deletion at delta run
  * from scratch, for thresholds at, between and beyond the sink sizes; X(delta) is nested; the
  * kept complex carries the values. */
TEST (WrapFiltration, PublicSurfacesEqualGlobalDeletionFromScratch)
{
  for (const auto& points : {torusSample (1000, 2), doubleTorusSample (1200, 3), cubeSample (500, 4)})
  {
    WrapParameters parameters = rawOutput ();
    parameters.filtration = true;
    const WrapResult r = computeWrap (points, parameters);
    ASSERT_FALSE (r.filtration.empty ());
    const std::vector<double>& sizes = r.filtration.sinkSizes ();
    ASSERT_GT (sizes.size (), 3u);
    EXPECT_TRUE (std::is_sorted (sizes.rbegin (), sizes.rend ()));
    EXPECT_EQ (canonical (r.filtration.surface (std::numeric_limits<double>::infinity ())), canonical (r.surface));

    std::vector<double> deltas = {std::numeric_limits<double>::infinity (), 1e9, sizes[0], sizes[1],
                                  0.5 * (sizes[2] + sizes[3]), sizes[sizes.size () / 2], 0.0};
    std::array<std::size_t, 4> previous{};
    previous.fill (~std::size_t (0));
    for (double delta : deltas)
    {
      SCOPED_TRACE ("delta " + std::to_string (delta));
      WrapParameters global = rawOutput ();
      global.deletion = SinkDeletion::global;
      global.threshold = Threshold::size (delta);
      EXPECT_EQ (canonical (r.filtration.surface (delta)), canonical (computeWrap (points, global).surface));
      const auto size = r.filtration.xSize (delta);
      for (int k = 0; k <= 3; ++k)
        EXPECT_LE (size[k], previous[k]) << "X(delta) shrinks as delta does";
      previous = size;
    }
    EXPECT_EQ (r.filtration.xSize (0.0)[3], 0u) << "below every sink, no tetrahedron is left";
    EXPECT_NE (canonical (r.filtration.surface (sizes[3])), canonical (r.surface));

    // The values in the kept complex say the same: in X (basic) iff finite or -inf.
    for (int k = 0; k <= 3; ++k)
    {
      ASSERT_EQ (r.complex[k].values.size (), r.complex[k].size ());
      for (std::size_t s = 0; s < r.complex[k].size (); ++s)
        EXPECT_EQ (bool (r.complex[k].in_x[s]), r.complex[k].values[s] < std::numeric_limits<double>::infinity ());
    }
  }
  WrapParameters none = rawOutput ();
  EXPECT_TRUE (computeWrap (torusSample (100, 1), none).filtration.empty ());
  EXPECT_THROW (Filtration ().surface (1.0), std::logic_error);
}

} // namespace
} // namespace pcl_wrap::test
