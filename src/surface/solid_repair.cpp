// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_repair.h"

#include "surface/link_cycle.h"
#include "surface/solid_euler.h"
#include "surface/solid_join.h"
#include "surface/solid_parts.h"
#include "surface/solid_voids.h"
#include "surface/surface_handles.h"
#include "surface/void_ties.h"
#include "util/parallel_for_each.h"
#include "util/union_find.h"
#include "wrap/boundary.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include <tbb/enumerable_thread_specific.h>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

/** What one thread needs to look at one vertex's star: reused from star to star. */
struct StarScratch
{
  Star star;
  Star corner; // the star of a corner of a move (trapsACorner())
  /** The ids of the block being mended (mendWithin()): no other thread moves a tetrahedron whose
    * vertices all lie in it. */
  std::uint32_t lo = 0, hi = ~std::uint32_t (0);
  std::vector<std::uint32_t> edge_uses, id_of_root;
  std::vector<std::array<std::uint32_t, 2>> link; // gatherSurfaceLink()'s edges
  UnionFind parts;
  SolidEulerChange::Scratch euler;
};

/** The number of consecutive vertex ids that mend() gives one task: the ids follow a space-filling
  * curve, so a block is a compact piece of space, and most stars lie within one block. */
constexpr std::uint32_t MENDING_BLOCK = 1u << 14;

/** How many tetrahedra cutSmallHandles() searches for a way round a move, at most: enough for a
  * handle a few spacings long, few enough to keep the search local. */
constexpr std::uint32_t HANDLE_REACH = 4096;

/** How many tetrahedra of the outside cutSmallHandles() searches for the hull, at most: the way
  * out of a concavity (a cup's inside, a tunnel's far end) is long, and a search that reaches the
  * hull stops there. */
constexpr std::uint32_t OUTSIDE_REACH = 1u << 18;

/** How many times run() looks for small handles, at most: again after each search that cut
  * something, only around the tetrahedra it moved. */
constexpr int HANDLE_PASSES = 4;

/** How many levels (SmallHandlePatches::level) on each side of a tunnel's middle cutSmallHandles()
  * slices its tube at. A patch is centred at a vertex, on the surface at one end of a web, whose
  * other end lies a ring further on: the slice that cuts it is at level 0 or 1 from there. */
constexpr int WAIST_LEVELS = 2;

/** The tetrahedra around one vertex (its star), or around one edge (its ring), and how they split
  * into connected parts on each side of the surface. */
class Repairer
{
public:
  Repairer (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, SolidLabels& labels, bool keep_buried)
    : tetrahedra_ (tetrahedra),
      complex_ (tetrahedra.complex ()),
      positions_ (positions),
      labels_ (labels),
      flipped_ (tetrahedra.size (), 0),
      unmended_ (complex_.numVertices (), 0)
  {
    if (!keep_buried)
      return;
    // The vertices buried from the start (every tetrahedron around them inside, none on the
    // hull) stay inside; one buried by a move is brought back.
    stays_buried_.assign (complex_.numVertices (), 1);
    for (std::uint32_t t = 0; t < labels_.inside.size (); ++t)
      for (int i = 0; i < 4; ++i)
        if (!labels_.inside[t])
          stays_buried_[tetrahedra_.vertex (t, i)] = 0;
        else if (tetrahedra_.neighbour (t, i) == OUTSIDE_HULL)
          for (int j = 1; j < 4; ++j)
            stays_buried_[tetrahedra_.vertex (t, (i + j) & 3)] = 0;
  }

  SolidRepair run (const Subcomplex& x)
  {
    SolidRepair done;
    bool one_part = false; // known to be one part, before the mending
    {
      // A volume's solid is X's: its parts are not joined.
      SideParts sides (tetrahedra_, labels_.inside,
                       stays_buried_.empty () ? SideParts::Sides::both : SideParts::Sides::outside);
      std::vector<std::uint32_t> in_voids; // those it keeps, sampled by the points
      done.flipped += fillUnsampledVoids (tetrahedra_, labels_, flipped_, sides, &in_voids).size ();
      if (stays_buried_.empty ()) // not a volume, whose solid is X's
      {
        // The ties across voids between separate objects, cut: the solid's parts are then found
        // again.
        const std::vector<std::uint32_t> untied =
            cutTiesAcrossVoids (tetrahedra_, positions_, in_voids, labels_, flipped_, sides);
        done.flipped += untied.size ();
        std::optional<SideParts> found_again;
        if (!untied.empty ())
          found_again.emplace (tetrahedra_, labels_.inside, SideParts::Sides::solid);
        // The parts the labelling cut apart, joined while their fragments are small, then the
        // points it left floating between them, brought on (each by a path to the solid).
        const SolidJoin join =
            joinPartsThroughX (tetrahedra_, x, positions_, (found_again ? *found_again : sides).solid (labels_.inside),
                               labels_, flipped_);
        done.flipped += join.moved.size ();
        done.flipped += bringFloatingPointsOn (tetrahedra_, x, positions_, labels_, flipped_).size ();
        one_part = join.parts == 1;
      }
    }
    // Most vertices need nothing: find the others on all threads, then mend them in order.
    const std::vector<std::uint8_t> needs = surfaceVerticesToMend ();
    std::vector<std::uint32_t> work;
    for (std::uint32_t v = 0; v < complex_.numVertices (); ++v)
      if (needs[v] && !staysBuried (v)) // a volume's inside: nothing to do
        work.push_back (v);
    std::vector<std::uint8_t> before_mending;
    if (one_part)
      before_mending = labels_.inside;
    mend (std::move (work), done);
    // The mending may cut the solid apart; most often it plainly has not.
    std::vector<std::uint32_t> joined;
    if (!one_part || !staysOnePart (tetrahedra_, labels_.inside, changedSince (before_mending)))
    {
      const SolidParts parts = solidParts (tetrahedra_, labels_.inside);
      joined = joinPartsThroughX (tetrahedra_, x, positions_, parts, labels_, flipped_).moved;
    }
    before_mending = {};
    // The mending leaves voids of its own (a tetrahedron whose star parts went different ways).
    const std::vector<std::uint32_t> filled = fillUnsampledVoidsNear (tetrahedra_, labels_, flipped_, movedSoFar ());
    joined.insert (joined.end (), filled.begin (), filled.end ());
    movedOutsideMending (joined);
    const std::vector<std::uint8_t> before_handles = labels_.inside;
    // Small handles, cut. A volume's solid, X's tetrahedra, has them too: X is contractible, but
    // where a sheet of its triangles spans a tunnel of its tetrahedra, the solid's surface goes
    // round that tunnel. The surface is kept while it is the solid's.
    std::optional<Boundary> surface = extractSolidBoundary (tetrahedra_, labels_.inside);
    SmallHandlePatches patches = smallHandlePatches (surface->triangles, complex_.numVertices (), nullptr, &positions_);
    std::vector<std::uint32_t> cut = cutSmallHandles (patches);
    for (int pass = 1; !cut.empty (); ++pass)
    {
      surface.reset ();
      joined.insert (joined.end (), cut.begin (), cut.end ());
      if (pass == HANDLE_PASSES)
        break;
      // A cut changes the surface around it, and what it leaves (a handle that no candidate of
      // the surface before took away, one the mending ties) is looked for again there.
      done.flipped += joined.size ();
      mend (tetrahedra_.verticesOf (joined), done);
      joined.clear ();
      const std::vector<std::uint32_t> near = tetrahedra_.verticesOf (cut);
      surface = extractSolidBoundary (tetrahedra_, labels_.inside);
      patches = smallHandlePatches (surface->triangles, complex_.numVertices (), &near, &positions_);
      cut = cutSmallHandles (patches);
    }
    if (surface && patches.has_genus)
    {
      // No small handle is left to cut, but a genus is: the tunnels too long for a small
      // handle's patch (a slit through a thin wall) are looked for once more, in wider patches.
      cut = cutSmallHandles (wideTunnelPatches (surface->triangles, complex_.numVertices (), positions_));
      if (!cut.empty ())
      {
        surface.reset ();
        joined.insert (joined.end (), cut.begin (), cut.end ());
      }
    }
    done.flipped += joined.size ();
    const std::size_t flipped_before = done.flipped;
    mend (tetrahedra_.verticesOf (joined), done);
    // The cuts and their mending leave voids as the first mending does: filled, then mended at
    // their corners (the void of one tetrahedron that touches the outside at a vertex).
    const std::vector<std::uint32_t> late =
        fillUnsampledVoidsNear (tetrahedra_, labels_, flipped_, changedSince (before_handles));
    if (!late.empty ())
    {
      done.flipped += late.size ();
      movedOutsideMending (late);
      mend (tetrahedra_.verticesOf (late), done);
    }
    if (done.flipped == flipped_before)
      done.surface = std::move (surface);
    for (std::uint32_t v = 0; v < unmended_.size (); ++v)
      if (unmended_[v])
        done.pinched.push_back (v);
    return done;
  }

private:
  using LinkEdge = std::array<std::uint32_t, 2>;

  /** Tells the weighing of moves, if made, that the tetrahedra \a moved changed side outside the
    * mending (which tells it of its own). */
  void movedOutsideMending (const std::vector<std::uint32_t>& moved)
  {
    if (euler_change_)
      for (std::uint32_t t : moved)
        euler_change_->changedSide (t);
  }

  /** The tetrahedra whose side is not the one in \a before, ascending. */
  std::vector<std::uint32_t> changedSince (const std::vector<std::uint8_t>& before) const
  {
    return indicesWhere (before.size (), [&] (std::size_t t) { return before[t] != labels_.inside[t]; });
  }

  /** The tetrahedra moved so far, ascending. */
  std::vector<std::uint32_t> movedSoFar () const
  {
    return indicesWhere (flipped_.size (), [&] (std::size_t t) { return flipped_[t] != 0; });
  }

  /** Whether a move out of the solid may cut it in two: not at all, into parts each larger than
    * HANDLE_REACH tetrahedra (a web between two objects), or into parts each with as many points
    * as an object (FRAGMENT_VERTICES; a neck across a gap of NECK_GAP spacings). */
  enum class Split
  {
    no,
    large,
    objects
  };

  /** A connected set of tetrahedra on one side whose move would cut a handle, and how strongly
    * the labelling put them there. */
  struct HandleCut
  {
    double weight;
    std::vector<std::uint32_t> tetrahedra; // sorted
    /** A slice of the solid across a tunnel's waist: it may cut a web across a gap, and so
      * split the solid. */
    bool web = false;
    /** A web across a neck (SmallHandlePatches::neck): it must cross a gap of NECK_GAP spacings. */
    bool neck = false;
    bool operator<(const HandleCut& o) const
    {
      return std::tie (weight, tetrahedra, web, neck) < std::tie (o.weight, o.tetrahedra, o.web, o.neck);
    }
    bool operator== (const HandleCut& o) const
    {
      return std::tie (weight, tetrahedra, web, neck) == std::tie (o.weight, o.tetrahedra, o.web, o.neck);
    }
  };

  /** Cuts the small handles of the solid's surface near which \a patches lie
    * (smallHandlePatches(), wideTunnelPatches()). The candidates are the connected parts (on one
    * side) of the stars of the vertices near one and of their stars' vertices whose move would
    * change the solid's Euler characteristic by +1, then the plugs of the patches near one
    * (handlePlugs()), found on all threads. Weakest first, star parts before plugs, a candidate
    * changes side, with the pockets it would enclose and the parts it would leave pinched
    * (closedMove()), if that still changes it by +1, the tetrahedra it leaves on its side stay
    * connected (within HANDLE_REACH tetrahedra from each), and the surface stays a 2-manifold at
    * its vertices. Such a move neither splits a part off nor opens or closes a void,
    * so it takes one handle away and makes none: there are at most as many moves as handles.
    * A web, a slice of the solid across a tunnel's waist (handlePlugs()), may instead split the
    * solid into parts each larger than the search's reach (a bridge between two objects, which
    * also raises the Euler characteristic by 1), if the edges it leaves on no tetrahedron of the
    * solid each join points a gap apart that the sampling resolves (seversResolvedGapsOnly()): a
    * tube of the solid across a gap no points sample, where a thin wire the points sample stays.
    * Returns the tetrahedra moved. */
  std::vector<std::uint32_t> cutSmallHandles (const SmallHandlePatches& patches)
  {
    std::vector<std::uint32_t> moved;
    if (patches.centres.empty ())
      return moved;
    hull_hops_.clear (); // the labels have changed since the last search
    const SolidEulerChange& euler_change = eulerChange ();
    StarScratch s;
    // The vertices of the stars of the centres; of those of tunnels only, outside parts only.
    std::array<std::vector<std::uint32_t>, 2> stars; // [1]: of tunnels
    for (std::size_t i = 0; i < patches.centres.size (); ++i)
    {
      if (patches.neck[i])
        continue; // its webs only
      tetrahedra_.gatherStar (patches.centres[i], s.star);
      stars[patches.tunnel[i]].insert (stars[patches.tunnel[i]].end (), s.star.tetrahedra ().begin (),
                                       s.star.tetrahedra ().end ());
    }
    // Each vertex once: one in both kinds of star gives the parts of both sides.
    std::vector<std::uint32_t> around = tetrahedra_.verticesOf (stars[0]), of_tunnels_only;
    const std::vector<std::uint32_t> of_tunnels = tetrahedra_.verticesOf (stars[1]);
    std::set_difference (of_tunnels.begin (), of_tunnels.end (), around.begin (), around.end (),
                         std::back_inserter (of_tunnels_only));
    std::vector<std::uint8_t> outside_only (around.size (), 0);
    around.insert (around.end (), of_tunnels_only.begin (), of_tunnels_only.end ());
    outside_only.resize (around.size (), 1);
    tbb::enumerable_thread_specific<std::pair<StarScratch, std::vector<HandleCut>>> found;
    parallelForEach (
        around.size (),
        [&] (std::size_t k) {
          auto& [scratch, candidates] = found.local ();
          tetrahedra_.gatherStar (around[k], scratch.star);
          const Parts parts = split (scratch, [] (int) { return true; });
          for (std::uint32_t p = 0; p < parts.side.size (); ++p)
            if (parts.weight[p] < std::numeric_limits<double>::infinity () && !(outside_only[k] && parts.side[p]))
            {
              std::vector<std::uint32_t> part = members (scratch, parts, p);
              std::sort (part.begin (), part.end ());
              if (euler_change (part, scratch.euler) == 1)
                candidates.push_back ({parts.weight[p], std::move (part)});
            }
        },
        16);
    const std::vector<HandleCut> candidates = gathered (found);
    const std::vector<HandleCut> plugs = handlePlugs (patches, tunnelSpacings (patches, s.star));
    std::vector<std::uint32_t> reached (tetrahedra_.size (), 0);
    std::uint32_t search = 0;
    for (const std::vector<HandleCut>* list : {&candidates, &plugs})
      for (const HandleCut& c : *list)
      {
        const bool side = inside (c.tetrahedra.front ());
        if (std::any_of (c.tetrahedra.begin (), c.tetrahedra.end (),
                         [&] (std::uint32_t t) { return inside (t) != side; }))
          continue; // moved in part
        if (euler_change (c.tetrahedra, s.euler) < 1)
          continue; // its handle is cut (+2: it also encloses a pocket, which may move with it)
        const double gap = c.neck ? NECK_GAP : UNRESOLVED_GAP;
        if (c.web && !seversResolvedGapsOnly (c.tetrahedra, s.star, gap))
          continue; // it would cut what the points sample (and so would any larger move)
        const std::vector<std::uint32_t> move = closedMove (c.tetrahedra, reached, search, s,
                                                            c.neck  ? Split::objects
                                                            : c.web ? Split::large
                                                                    : Split::no);
        if (move.empty () || (c.web && move != c.tetrahedra && !seversResolvedGapsOnly (move, s.star, gap)))
          continue; // its handle is cut, or the move would cut a side in two, leave a pinch or cut a wire
        for (std::uint32_t t : move)
        {
          labels_.inside[t] ^= 1u;
          euler_change_->changedSide (t);
          flipped_[t] = 1;
          moved.push_back (t);
        }
      }
    return moved;
  }

  /** The lists of all threads in one, sorted, each candidate once (the patches overlap). */
  static std::vector<HandleCut> gathered (
      tbb::enumerable_thread_specific<std::pair<StarScratch, std::vector<HandleCut>>>& found)
  {
    std::vector<HandleCut> all;
    for (auto& [scratch, list] : found)
      std::move (list.begin (), list.end (), std::back_inserter (all));
    std::sort (all.begin (), all.end ());
    all.erase (std::unique (all.begin (), all.end ()), all.end ());
    return all;
  }

  /** The plugs of \a patches: per patch, the connected parts (on one side, the outside only for
    * a tunnel) of the tetrahedra whose four vertices are in it, whose move would raise the
    * solid's Euler characteristic (by more than 1 where it encloses pockets, which closedMove()
    * adds). Where a patch goes round a tube too wide for one star to cut, the tube's own
    * tetrahedra within the patch make a slice of it: moved across, they cut the tube (a bridge of
    * the solid) or fill it (a tunnel). And per tunnel, the webs: for each two consecutive levels
    * of its patch (SmallHandlePatches::level) within WAIST_LEVELS of its middle, the connected
    * parts of the solid's tetrahedra within the patch with a corner at or below the lower level
    * and one at or above the higher, a slice across the tube that cuts it where it is solid.
    * Such a slice also holds the solid of the objects at the tube's ends wherever their corners
    * span the two levels. So there are gap slices too: the same, of the tetrahedra alone that
    * hold an edge across a gap the sampling resolves (seversResolvedGapsOnly()'s rule; \a spacings
    * per vertex of a tunnel's patch) whose ends' levels span the two levels, or one of two
    * consecutive such pairs (a web one edge long can have the same level at both its ends); a web
    * between two objects is made of such tetrahedra. Sorted, weakest first. */
  std::vector<HandleCut> handlePlugs (const SmallHandlePatches& patches, const std::vector<double>& spacings) const
  {
    const SolidEulerChange& euler_change = *euler_change_;
    tbb::enumerable_thread_specific<std::pair<StarScratch, std::vector<HandleCut>>> found;
    parallelForEach (
        patches.centres.size (),
        [&] (std::size_t i) {
          auto& found_here = found.local ();
          StarScratch& scratch = found_here.first;
          std::vector<HandleCut>& plugs = found_here.second; // not bindings: the lambda below uses them
          const auto first = patches.vertices.begin () + patches.begin[i],
                     last = patches.vertices.begin () + patches.begin[i + 1];
          const std::vector<std::uint32_t> within = tetrahedraWithin (first, last, scratch.star);
          const auto add = [&] (std::vector<std::uint32_t>& part, bool web) {
            plugs.push_back ({0.0, std::move (part), web, patches.neck[i] != 0});
          };
          if (!patches.neck[i]) // a neck's webs only
            for (std::vector<std::uint32_t>& part : partsOnOneSide (within, scratch.parts))
              if (!(patches.tunnel[i] && inside (part.front ())))
                add (part, false);
          if (!patches.tunnel[i] && !patches.neck[i])
            return;
          // The solid's tetrahedra within the patch, each with the range of its corners' levels.
          std::vector<std::pair<std::uint32_t, std::array<int, 2>>> solid;
          for (std::uint32_t t : within)
            if (inside (t))
            {
              std::array<int, 2> range{INT8_MAX, INT8_MIN};
              for (int j = 0; j < 4; ++j)
              {
                const int level =
                    patches
                        .level[std::lower_bound (first, last, tetrahedra_.vertex (t, j)) - patches.vertices.begin ()];
                range = {std::min (range[0], level), std::max (range[1], level)};
              }
              solid.push_back ({t, range});
            }
          // Near the tube's middle: the patch's centre is on the surface at one end of a web.
          for (int cut = -WAIST_LEVELS; cut < WAIST_LEVELS; ++cut)
          {
            std::vector<std::uint32_t> waist; // across the tube, between levels cut and cut + 1
            for (const auto& [t, range] : solid)
              if (range[0] <= cut && cut < range[1])
                waist.push_back (t);
            for (std::vector<std::uint32_t>& part : partsOnOneSide (waist, scratch.parts))
              add (part, true);
          }
          // The solid's tetrahedra with an edge across a resolved gap between two levels, each
          // with the range of those edges' ends' levels.
          const auto at = [&] (std::uint32_t v) {
            return std::lower_bound (first, last, v) - patches.vertices.begin ();
          };
          std::vector<std::pair<std::uint32_t, std::array<int, 2>>> across;
          for (const auto& [t, range] : solid)
          {
            std::array<int, 2> spans{INT8_MAX, INT8_MIN};
            for (int a = 0; a < 4; ++a)
              for (int b = a + 1; b < 4; ++b)
              {
                const std::uint32_t u = tetrahedra_.vertex (t, a), w = tetrahedra_.vertex (t, b);
                const auto ku = at (u), kw = at (w);
                if (patches.level[ku] != patches.level[kw] &&
                    resolvedGap (positions_[u], positions_[w], spacings[ku], spacings[kw]))
                  spans = {std::min ({spans[0], int (patches.level[ku]), int (patches.level[kw])}),
                           std::max ({spans[1], int (patches.level[ku]), int (patches.level[kw])})};
              }
            if (spans[0] < spans[1])
              across.push_back ({t, spans});
          }
          for (int cut = -WAIST_LEVELS; cut < WAIST_LEVELS; ++cut)
            for (int pairs = 1; pairs <= 2; ++pairs)
            {
              std::vector<std::uint32_t> waist; // across the gap, between cut and cut + pairs
              for (const auto& [t, spans] : across)
                if (spans[0] <= cut + pairs - 1 && cut < spans[1])
                  waist.push_back (t);
              for (std::vector<std::uint32_t>& part : partsOnOneSide (waist, scratch.parts))
                add (part, true);
            }
        },
        4);
    // The patches overlap, and so do their plugs: each is weighed once.
    std::vector<HandleCut> plugs = gathered (found);
    std::vector<std::uint8_t> raises (plugs.size ());
    tbb::enumerable_thread_specific<SolidEulerChange::Scratch> scratches;
    parallelForEach (plugs.size (), [&] (std::size_t k) {
      HandleCut& plug = plugs[k];
      for (std::uint32_t t : plug.tetrahedra)
        plug.weight += labels_.margin[t];
      raises[k] = euler_change (plug.tetrahedra, scratches.local ()) >= 1;
    });
    std::vector<HandleCut> kept;
    for (std::size_t k = 0; k < plugs.size (); ++k)
      if (raises[k])
        kept.push_back (std::move (plugs[k]));
    std::sort (kept.begin (), kept.end ());
    return kept;
  }

  /** Per vertex of \a patches.vertices: the sample's spacing around it (spacingAround()) in the
    * patch of a tunnel, for the gap slices of handlePlugs(); 0 elsewhere. \a star is scratch. */
  std::vector<double> tunnelSpacings (const SmallHandlePatches& patches, Star& star)
  {
    std::vector<double> spacings (patches.vertices.size (), 0.0);
    for (std::size_t i = 0; i < patches.centres.size (); ++i)
      if (patches.tunnel[i] || patches.neck[i])
        for (std::uint32_t k = patches.begin[i]; k < patches.begin[i + 1]; ++k)
          spacings[k] = sampleSpacingAround (patches.vertices[k], star);
    return spacings;
  }

  /** spacingAround() at vertex \a v, kept from call to call (the patches overlap), as are the
    * spacings at vertices it reads. \a star is scratch. */
  double sampleSpacingAround (std::uint32_t v, Star& star)
  {
    if (spacing_at_.empty ())
    {
      spacing_at_.assign (complex_.numVertices (), std::numeric_limits<double>::quiet_NaN ());
      spacing_around_.assign (complex_.numVertices (), std::numeric_limits<double>::quiet_NaN ());
    }
    if (std::isnan (spacing_around_[v]))
    {
      tetrahedra_.gatherStar (v, star);
      spacing_around_[v] = spacingAround (tetrahedra_, star, v, positions_, spacing_at_, neighbour_star_);
    }
    return spacing_around_[v];
  }

  /** The tetrahedra whose four vertices are all in [\a first, \a last) (ascending vertex ids),
    * ascending; \a star is scratch. */
  template <class It>
  std::vector<std::uint32_t> tetrahedraWithin (It first, It last, Star& star) const
  {
    const auto within = [&] (std::uint32_t v) { return std::binary_search (first, last, v); };
    std::vector<std::uint32_t> tetrahedra;
    for (auto v = first; v != last; ++v)
    {
      tetrahedra_.gatherStar (*v, star);
      for (std::uint32_t t : star.tetrahedra ())
      {
        bool all = true; // and v is the lowest of them, so each is listed once
        for (int j = 0; j < 4 && all; ++j)
          all = tetrahedra_.vertex (t, j) >= *v && within (tetrahedra_.vertex (t, j));
        if (all)
          tetrahedra.push_back (t);
      }
    }
    std::sort (tetrahedra.begin (), tetrahedra.end ());
    return tetrahedra;
  }

  /** The connected parts of \a tetrahedra (ascending), each on one side, joined across their
    * facets; each part ascending. \a sets is scratch. */
  std::vector<std::vector<std::uint32_t>> partsOnOneSide (const std::vector<std::uint32_t>& tetrahedra,
                                                          UnionFind& sets) const
  {
    sets.reset (tetrahedra.size ());
    for (std::uint32_t k = 0; k < tetrahedra.size (); ++k)
      for (int j = 0; j < 4; ++j)
      {
        const std::uint32_t u = tetrahedra_.neighbour (tetrahedra[k], j);
        const auto at = std::lower_bound (tetrahedra.begin (), tetrahedra.end (), u);
        if (u != OUTSIDE_HULL && at != tetrahedra.end () && *at == u && inside (u) == inside (tetrahedra[k]))
          sets.attach (static_cast<std::uint32_t> (at - tetrahedra.begin ()), k);
      }
    // The tetrahedra in the order of their roots, each root's in ascending order.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> by_root; // root, index
    for (std::uint32_t k = 0; k < tetrahedra.size (); ++k)
      by_root.push_back ({sets.find (k), k});
    std::sort (by_root.begin (), by_root.end ());
    std::vector<std::vector<std::uint32_t>> parts;
    for (std::size_t k = 0; k < by_root.size (); ++k)
    {
      if (k == 0 || by_root[k].first != by_root[k - 1].first)
        parts.emplace_back ();
      parts.back ().push_back (tetrahedra[by_root[k].second]);
    }
    return parts;
  }

  /** Does moving \a move (of the solid) out sever only points a gap apart that the sampling
    * resolves? An edge of its tetrahedra that no other tetrahedron of the solid keeps must be
    * longer than UNRESOLVED_GAP times the smaller of the sample's spacings around its ends
    * (spacingAround()), or its ends must stay tied through a third point by edges the solid
    * keeps. \a star is scratch. */
  bool seversResolvedGapsOnly (const std::vector<std::uint32_t>& move, Star& star, double gap = UNRESOLVED_GAP)
  {
    const auto moving = [&] (std::uint32_t t) { return std::binary_search (move.begin (), move.end (), t); };
    const auto keeps = [&] (std::uint32_t t) { return inside (t) && !moving (t); };
    const std::vector<std::uint32_t> corners = tetrahedra_.verticesOf (move);
    const auto at = [&] (std::uint32_t v) {
      return static_cast<std::size_t> (std::lower_bound (corners.begin (), corners.end (), v) - corners.begin ());
    };
    // Per vertex of the move, where an edge needs them: its neighbours along the edges the solid
    // keeps (sorted), and the sample's spacing around it.
    std::vector<std::vector<std::uint32_t>> kept (corners.size ());
    std::vector<std::uint8_t> kept_known (corners.size (), 0);
    const auto keptOf = [&] (std::size_t k) -> const std::vector<std::uint32_t>& {
      if (kept_known[k])
        return kept[k];
      kept_known[k] = 1;
      tetrahedra_.gatherStar (corners[k], star);
      for (std::uint32_t t : star.tetrahedra ())
        if (keeps (t))
          for (int i = 0; i < 4; ++i)
            kept[k].push_back (tetrahedra_.vertex (t, i));
      std::sort (kept[k].begin (), kept[k].end ());
      kept[k].erase (std::unique (kept[k].begin (), kept[k].end ()), kept[k].end ());
      return kept[k];
    };
    std::vector<double> spacing (corners.size (), std::numeric_limits<double>::quiet_NaN ());
    const auto spacingOf = [&] (std::size_t k) {
      if (std::isnan (spacing[k]))
        spacing[k] = sampleSpacingAround (corners[k], star);
      return spacing[k];
    };
    std::vector<std::uint32_t> common;
    for (std::uint32_t t : move)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
        {
          if (tetrahedra_.anyRoundEdge (t, i, j, keeps))
            continue; // kept
          const std::size_t a = at (tetrahedra_.vertex (t, i)), b = at (tetrahedra_.vertex (t, j));
          if (resolvedGap (positions_[corners[a]], positions_[corners[b]], spacingOf (a), spacingOf (b), gap))
            continue; // a gap the sampling resolves
          common.clear ();
          const std::vector<std::uint32_t>&kept_a = keptOf (a), &kept_b = keptOf (b);
          std::set_intersection (kept_a.begin (), kept_a.end (), kept_b.begin (), kept_b.end (),
                                 std::back_inserter (common));
          if (common.empty ())
            return false;
        }
    return true;
  }

  /** The move that cuts a handle with \a part (sorted, all on one side): \a part, the pockets
    * it encloses (moveKeepingSidesConnected()), and the weaker parts of its side that it would leave
    * apart around a vertex of it (a pinch), grown so a few times; empty if the move changes the
    * solid's Euler characteristic by other than +1, cuts its side in two (but as \a splits
    * allows), or leaves the surface other than a 2-manifold at its vertices. */
  std::vector<std::uint32_t> closedMove (std::vector<std::uint32_t> part, std::vector<std::uint32_t>& reached,
                                         std::uint32_t& search, StarScratch& s, Split splits)
  {
    const std::uint8_t side = inside (part.front ());
    for (int grown = 0; grown <= 2; ++grown)
    {
      std::vector<std::uint32_t> move = moveKeepingSidesConnected (part, reached, search, splits);
      if (move.empty () || (*euler_change_) (move, s.euler) != 1)
        return {};
      for (std::uint32_t t : move)
        labels_.inside[t] ^= 1u;
      bool manifold = true;
      std::vector<std::uint32_t> apart;
      for (std::uint32_t v : tetrahedra_.verticesOf (move))
      {
        tetrahedra_.gatherStar (v, s.star);
        const Parts parts = split (s, [] (int) { return true; });
        if (parts.count[0] + parts.count[1] <= 2 && pinchedEdge (s) == NONE)
          continue;
        manifold = false;
        // All of the side the move left but its strongest part.
        std::uint32_t strongest = NONE;
        for (std::uint32_t p = 0; p < parts.side.size (); ++p)
          if (parts.side[p] == side && (strongest == NONE || parts.weight[p] > parts.weight[strongest]))
            strongest = p;
        for (std::uint32_t p = 0; p < parts.side.size (); ++p)
          if (parts.side[p] == side && p != strongest && parts.movable[p])
          {
            const std::vector<std::uint32_t> more = members (s, parts, p);
            apart.insert (apart.end (), more.begin (), more.end ());
          }
      }
      for (std::uint32_t t : move)
        labels_.inside[t] ^= 1u;
      if (manifold)
        return move;
      if (apart.empty ())
        return {};
      part = std::move (move);
      part.insert (part.end (), apart.begin (), apart.end ());
      std::sort (part.begin (), part.end ());
      part.erase (std::unique (part.begin (), part.end ()), part.end ());
    }
    return {};
  }

  /** The tetrahedra to move for \a part (sorted, all on one side) if the tetrahedra across its
    * facets on its side stay connected without it, through at most HANDLE_REACH tetrahedra of that
    * side from each (and, for the outside, through the space beyond the hull, which a search
    * goes on looking for up to OUTSIDE_REACH tetrahedra, nearest the hull first), or, for the
    * solid as \a splits allows, if no search from them ends within HANDLE_REACH (what is left is
    * connected or in large parts), or none ends in a part of fewer than FRAGMENT_VERTICES points;
    * empty if not. A move into the solid may enclose small pockets
    * of the outside (a search from them ends within the reach, short of the hull): they move with
    * it, as fillUnsampledVoids() would fill them. \a reached: per tetrahedron, the last search
    * to reach it; \a search: the last search's number, counted on by one per search. */
  std::vector<std::uint32_t> moveKeepingSidesConnected (const std::vector<std::uint32_t>& part,
                                                        std::vector<std::uint32_t>& reached, std::uint32_t& search,
                                                        Split splits)
  {
    const bool side = inside (part.front ());
    const auto inPart = [&] (std::uint32_t t) { return std::binary_search (part.begin (), part.end (), t); };
    std::vector<std::uint32_t> seeds;
    bool hull_seed = false;
    for (std::uint32_t t : part)
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t u = tetrahedra_.neighbour (t, i);
        if (u == OUTSIDE_HULL)
          hull_seed = hull_seed || !side;
        else if (inside (u) == side && !inPart (u))
          seeds.push_back (u);
      }
    // One search from each seed that no earlier search reached. What is left of the side is
    // connected when one search reached all of it (and the hull, if the part touched it), or
    // when every search reached the hull, beyond which the outside is one. For the solid, that
    // is all the first search has to find: it stops once it has reached every seed, and where it
    // has not, and no split is allowed, the move is refused then. For the outside, a search
    // stops once it has reached the hull, or a tetrahedron an earlier search reached (which
    // reached the hull: the move is refused at the first search of the outside that does not).
    const std::uint32_t first_search = search + 1;
    std::size_t searches = 0, small = 0;
    std::vector<std::uint32_t> move = part, queue, distinct_seeds;
    if (side)
    {
      distinct_seeds = seeds;
      std::sort (distinct_seeds.begin (), distinct_seeds.end ());
      distinct_seeds.erase (std::unique (distinct_seeds.begin (), distinct_seeds.end ()), distinct_seeds.end ());
    }
    std::size_t seeds_left = distinct_seeds.size (); // of the solid, not reached by the first search
    for (std::uint32_t seed : seeds)
    {
      if (reached[seed] >= first_search)
        continue;
      if (side && searches == 1 && splits == Split::no)
        return {}; // the solid left is not connected
      const std::uint32_t mine = ++search;
      queue.assign (1, seed);
      reached[seed] = mine;
      const bool first = searches == 0;
      seeds_left -= side && first;
      bool hull_reached = false;
      const auto reach = [&] (std::uint32_t t) {
        for (int i = 0; i < 4; ++i)
        {
          const std::uint32_t u = tetrahedra_.neighbour (t, i);
          if (u == OUTSIDE_HULL)
            hull_reached = true;
          else if (reached[u] >= first_search && reached[u] != mine) // an earlier search's
            hull_reached = hull_reached || !side;
          else if (reached[u] != mine && inside (u) == side && !inPart (u))
          {
            reached[u] = mine;
            queue.push_back (u);
            seeds_left -= side && first && std::binary_search (distinct_seeds.begin (), distinct_seeds.end (), u);
          }
        }
      };
      std::size_t k = 0;
      for (; k < queue.size () && queue.size () <= HANDLE_REACH && !(side && first && seeds_left == 0) &&
             !(!side && hull_reached);
           ++k)
        reach (queue[k]);
      if (!side && !hull_reached && k < queue.size ())
      {
        // The way out of a cup's inside is long: the search goes on towards the hull, nearest
        // first, until it is reached or the outside there is found enclosed.
        const std::vector<std::uint32_t>& hops = hullHops ();
        using Entry = std::pair<std::uint32_t, std::uint32_t>; // hops, tetrahedron
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> front;
        for (; k < queue.size (); ++k)
          front.push ({hops[queue[k]], queue[k]});
        while (!front.empty () && !hull_reached && queue.size () <= OUTSIDE_REACH)
        {
          const std::size_t before = queue.size ();
          reach (front.top ().second);
          front.pop ();
          for (std::size_t j = before; j < queue.size (); ++j)
            front.push ({hops[queue[j]], queue[j]});
        }
      }
      if (!side && !hull_reached && queue.size () <= HANDLE_REACH)
        move.insert (move.end (), queue.begin (), queue.end ()); // a pocket
      else if (!side && !hull_reached)
        return {}; // the outside left is not connected
      else
      {
        ++searches;
        // A part of the solid that the search went all round is an object of its own if it has
        // as many points as one (FRAGMENT_VERTICES): a split may leave it apart.
        small += queue.size () <= HANDLE_REACH &&
                 (splits != Split::objects || tetrahedra_.verticesOf (queue).size () < FRAGMENT_VERTICES);
      }
    }
    // Every search of the outside that counts reached the hull (one that did not refused the
    // move); the solid is connected when one search reached all of it.
    const bool connected = searches == 0 ? hull_seed : !side || searches == 1;
    if (!connected && !(side && splits != Split::no && small == 0))
      return {};
    std::sort (move.begin (), move.end ());
    return move;
  }

  /** Per tetrahedron of the outside, how many facets a path through the outside crosses to the
    * hull at least (as the labels were when first asked for in a search for handles); the most
    * for the others. */
  const std::vector<std::uint32_t>& hullHops ()
  {
    if (!hull_hops_.empty ())
      return hull_hops_;
    hull_hops_.assign (tetrahedra_.size (), std::numeric_limits<std::uint32_t>::max ());
    std::vector<std::uint32_t> front, next;
    for (std::uint32_t t = 0; t < tetrahedra_.size (); ++t)
      if (!inside (t) && tetrahedra_.onHull (t))
      {
        hull_hops_[t] = 0;
        front.push_back (t);
      }
    for (std::uint32_t hops = 1; !front.empty (); ++hops)
    {
      next.clear ();
      for (std::uint32_t t : front)
        for (int i = 0; i < 4; ++i)
        {
          const std::uint32_t u = tetrahedra_.neighbour (t, i);
          if (u != OUTSIDE_HULL && !inside (u) && hull_hops_[u] > hops)
          {
            hull_hops_[u] = hops;
            next.push_back (u);
          }
        }
      front.swap (next);
    }
    return hull_hops_;
  }

  /** Per vertex, whether mendVertex() may have something to do there: the vertex is off the
    * surface, or the surface's triangles around it do not make one fan. Found from the surface
    * triangles alone, on all threads: each gives its opposite edge to the link of each of its
    * vertices; a vertex is as it should be when those edges make one cycle. */
  std::vector<std::uint8_t> surfaceVerticesToMend () const
  {
    const std::size_t n = complex_.size (3);
    std::vector<std::uint8_t> needs (complex_.numVertices (), 1);
    std::vector<std::size_t> begin;
    bucketInParallel<LinkEdge> (
        n, complex_.numVertices (),
        [&] (std::size_t t, auto put) {
          if (!labels_.inside[t])
            return;
          const std::uint32_t* v = complex_.vertices (3, static_cast<SimplexId> (t));
          for (int i = 0; i < 4; ++i)
            if (!inside (tetrahedra_.neighbour (static_cast<std::uint32_t> (t), i)))
            {
              const std::uint32_t a = v[(i + 1) & 3], b = v[(i + 2) & 3], c = v[(i + 3) & 3];
              put (a, LinkEdge{b, c});
              put (b, LinkEdge{c, a});
              put (c, LinkEdge{a, b});
            }
        },
        begin,
        [&] (std::size_t v, auto first, auto last) { needs[v] = !isOneCycle (first, last); });
    return needs;
  }

  /** Mends the vertices of \a work (ascending) and those that every move may concern: the lowest
    * first, then the vertices of each tetrahedron moved and the far corners of its neighbours on
    * the side it left. On all threads, each block of MENDING_BLOCK consecutive ids mends those of
    * its vertices whose star has vertices of the block only; then blocks shifted by half their
    * length, and blocks sixteen times longer, mend those left, and the rest are mended one by one.
    * A vertex's mending reads the labels of its star, of the tetrahedra across its star's facets
    * and around its star's edges, and the counts at its star's vertices, and moves tetrahedra of
    * its star. Two vertices whose stars lie in different blocks are at least three edges apart, so
    * neither reads what the other moves: the result depends on the labels alone, not on the
    * threads. */
  void mend (std::vector<std::uint32_t> work, SolidRepair& done)
  {
    if (work.empty ())
      return;
    eulerChange ();
    std::vector<std::uint8_t> queued (complex_.numVertices (), 0);
    tbb::enumerable_thread_specific<StarScratch> scratches;
    // Blocks, then blocks shifted by half their length, then both again sixteen times longer.
    for (const auto& [length, shift] : {std::pair{MENDING_BLOCK, 0u},
                                        {MENDING_BLOCK, MENDING_BLOCK / 2},
                                        {16 * MENDING_BLOCK, 0u},
                                        {16 * MENDING_BLOCK, 8 * MENDING_BLOCK}})
      work = mendInBlocks (work, length, shift, queued, scratches, done);
    std::reverse (work.begin (), work.end ());
    std::vector<std::uint32_t> none;
    done.flipped += mendWithin (std::move (work), 0, complex_.numVertices (), queued, scratches.local (), none);
  }

  /** mendWithin() on all threads, in the blocks of \a length ids that start at multiples of it
    * plus \a shift; returns the vertices left, ascending. */
  std::vector<std::uint32_t> mendInBlocks (const std::vector<std::uint32_t>& work, std::uint32_t length,
                                           std::uint32_t shift, std::vector<std::uint8_t>& queued,
                                           tbb::enumerable_thread_specific<StarScratch>& scratches, SolidRepair& done)
  {
    const std::uint32_t n = complex_.numVertices ();
    const std::size_t blocks = (std::size_t (n) + shift + length - 1) / length;
    std::vector<std::vector<std::uint32_t>> left (blocks);
    std::vector<std::size_t> moved (blocks, 0);
    parallelForEach (
        blocks,
        [&] (std::size_t b) {
          const std::size_t start = b * length;
          const auto lo = static_cast<std::uint32_t> (start < shift ? 0 : start - shift);
          const auto hi = static_cast<std::uint32_t> (std::min<std::size_t> (n, start + length - shift));
          std::vector<std::uint32_t> stack (std::lower_bound (work.begin (), work.end (), lo),
                                            std::lower_bound (work.begin (), work.end (), hi));
          std::reverse (stack.begin (), stack.end ());
          moved[b] = mendWithin (std::move (stack), lo, hi, queued, scratches.local (), left[b]);
        },
        1);
    std::vector<std::uint32_t> rest;
    for (std::size_t b = 0; b < blocks; ++b)
    {
      done.flipped += moved[b];
      rest.insert (rest.end (), left[b].begin (), left[b].end ());
    }
    std::sort (rest.begin (), rest.end ());
    rest.erase (std::unique (rest.begin (), rest.end ()), rest.end ());
    return rest;
  }

  /** Mends the vertices of \a stack (popped from the back) and those every move queues (the
    * tetrahedron's vertices, the far corners of its neighbours on the side it left), each whose
    * star has vertices in [lo, hi) only; the others go to \a left. Returns the number of
    * tetrahedra moved. */
  std::size_t mendWithin (std::vector<std::uint32_t> stack, std::uint32_t lo, std::uint32_t hi,
                          std::vector<std::uint8_t>& queued, StarScratch& s, std::vector<std::uint32_t>& left)
  {
    for (std::uint32_t v : stack)
      queued[v] = 1;
    std::size_t moved = 0;
    while (!stack.empty ())
    {
      const std::uint32_t v = stack.back ();
      stack.pop_back ();
      queued[v] = 0;
      if (!stack.empty ())
        tetrahedra_.prefetchStar (stack.back ());
      tetrahedra_.gatherStar (v, s.star);
      if (!starWithin (s.star, lo, hi))
      {
        left.push_back (v);
        continue;
      }
      if (oneFan (s)) // most often so, once a neighbour's move has queued v
      {
        unmended_[v] = 0;
        continue;
      }
      bool pinched = false;
      s.lo = lo;
      s.hi = hi;
      const std::vector<std::uint32_t> flips = mendVertex (s, pinched);
      unmended_[v] = flips.empty () && pinched;
      for (std::uint32_t t : flips)
      {
        labels_.inside[t] ^= 1u;
        euler_change_->changedSide (t);
        flipped_[t] = 1;
        ++moved;
        // Its vertices, and the far corner of each neighbour on the side it left: that neighbour
        // now touches the other side, so a buried or floating point there may have a way on.
        for (int i = 0; i < 4; ++i)
        {
          queue (complex_.vertex (3, t, i), lo, hi, queued, stack, left);
          const std::uint32_t across = tetrahedra_.neighbour (t, i);
          if (across != OUTSIDE_HULL && inside (across) != inside (t))
            queue (tetrahedra_.vertex (across, tetrahedra_.mirrorIndex (t, i)), lo, hi, queued, stack, left);
        }
      }
    }
    return moved;
  }

  /** Puts \a u on mendWithin()'s \a stack, unless it is there; a vertex outside [lo, hi), which
    * another block may be mending, goes to \a left. */
  static void queue (std::uint32_t u, std::uint32_t lo, std::uint32_t hi, std::vector<std::uint8_t>& queued,
                     std::vector<std::uint32_t>& stack, std::vector<std::uint32_t>& left)
  {
    if (u < lo || u >= hi)
      left.push_back (u);
    else if (!queued[u])
    {
      queued[u] = 1;
      stack.push_back (u);
    }
  }

  /** The weighing of moves by the solid's Euler characteristic, made (counting the inside
    * tetrahedra at each vertex) when first needed. */
  const SolidEulerChange& eulerChange ()
  {
    if (!euler_change_)
      euler_change_.emplace (tetrahedra_, labels_.inside);
    return *euler_change_;
  }

  bool starWithin (const Star& star, std::uint32_t lo, std::uint32_t hi) const
  {
    return std::all_of (star.tetrahedra ().begin (), star.tetrahedra ().end (),
                        [&] (std::uint32_t t) { return within (t, lo, hi); });
  }

  /** Are the vertices of tetrahedron \a t all in [lo, hi)? */
  bool within (std::uint32_t t, std::uint32_t lo, std::uint32_t hi) const
  {
    for (int i = 0; i < 4; ++i)
      if (tetrahedra_.vertex (t, i) < lo || tetrahedra_.vertex (t, i) >= hi)
        return false;
    return true;
  }

  /** Connected parts of the gathered tetrahedra: part[k] for star[k], count per side. */
  struct Parts
  {
    std::vector<std::uint32_t> part;
    std::array<std::size_t, 2> count{}; // [0] outside, [1] inside
    std::vector<std::uint8_t> side;     // per part
    std::vector<double> weight;         // per part: summed margins (infinite beyond the hull)
    std::vector<std::uint8_t> movable;  // per part: none moved before, none barred (mayGoInside())
  };

  bool inside (std::uint32_t t) const { return t != OUTSIDE_HULL && labels_.inside[t]; }

  /** May the mending of a buried or floating point move \a t across to bring it on (mendVertex())?
    * Not if it moved before or spans two groups of the sample; yes if a neighbour of it is on the
    * other side (\a other_side, of a tetrahedron id or OUTSIDE_HULL). */
  template <class OtherSide>
  bool bringsOn (std::uint32_t t, const OtherSide& other_side) const
  {
    if (flipped_[t] || !labels_.oneGroup (tetrahedra_.vertices (t)))
      return false;
    for (int i = 0; i < 4; ++i)
      if (other_side (tetrahedra_.neighbour (t, i)))
        return true;
    return false;
  }

  /** In a volume, was \a v buried from the start (and so stays inside)? */
  bool staysBuried (std::uint32_t v) const { return !stays_buried_.empty () && stays_buried_[v]; }

  /** The connected parts, on each side, of the star's tetrahedra for which \a keep (index into
    * s.star) holds, joined across facets that contain its vertex and every vertex \a through
    * requires. */
  template <class Keep, class Through = bool (*) (std::uint32_t, int)>
  Parts split (
      StarScratch& s, const Keep& keep, const Through& through = [] (std::uint32_t, int) { return true; }) const
  {
    const std::size_t m = s.star.size ();
    UnionFind& sets = s.parts;
    sets.reset (m + 1); // the star's tetrahedra, then the outside beyond the hull
    bool touches_hull = false;
    for (std::size_t k = 0; k < m; ++k)
    {
      if (!keep (static_cast<int> (k)))
        continue;
      const std::uint32_t t = s.star[k];
      for (int i = 0; i < 4; ++i)
      {
        if (tetrahedra_.vertex (t, i) == s.star.vertex () || !through (t, i))
          continue;
        const std::uint32_t u = tetrahedra_.neighbour (t, i);
        if (u == OUTSIDE_HULL)
        {
          touches_hull = true;
          if (!inside (t))
            sets.attach (static_cast<std::uint32_t> (k), static_cast<std::uint32_t> (m));
        }
        else if (inside (u) == inside (t) && u > t)
        {
          const std::uint32_t j = s.star.indexOf (u);
          if (j != Star::NOT_IN_STAR && keep (static_cast<int> (j)))
            sets.attach (static_cast<std::uint32_t> (k), j);
        }
      }
    }
    Parts parts;
    parts.part.assign (m + 1, NONE);
    std::vector<std::uint32_t>& id_of_root = s.id_of_root;
    id_of_root.assign (m + 1, NONE);
    for (std::size_t k = 0; k <= m; ++k)
    {
      if (k == m ? !touches_hull : !keep (static_cast<int> (k)))
        continue;
      const std::uint32_t r = sets.find (static_cast<std::uint32_t> (k));
      if (id_of_root[r] == NONE)
      {
        id_of_root[r] = static_cast<std::uint32_t> (parts.side.size ());
        const std::uint8_t side = k == m ? 0 : inside (s.star[k]);
        parts.side.push_back (side);
        parts.weight.push_back (0.0);
        parts.movable.push_back (1);
        ++parts.count[side];
      }
      const std::uint32_t p = id_of_root[r];
      parts.part[k] = p;
      if (k == m)
      {
        parts.weight[p] = std::numeric_limits<double>::infinity ();
        parts.movable[p] = 0;
      }
      else
      {
        const std::uint32_t t = s.star[k];
        parts.weight[p] += labels_.margin[t];
        if (flipped_[t] || (!inside (t) && !labels_.mayGoInside (tetrahedra_.vertices (t))))
          parts.movable[p] = 0;
      }
    }
    return parts;
  }

  /** The part to move: the weakest movable part whose side has more than one part (moving the only
    * part of a side would take v off the surface), of those that make no handle if any, else of
    * those that make one (in a volume, whose solid is X's, the weakest); NONE if none. A handle
    * here is one the points do not show: two sheets of the surface that touch get tied by a tube,
    * where cutting them apart keeps the solid's topology. A part whose move would make several
    * handles at once is never moved (on a noisy dino, a fan of long tetrahedra from a leg across
    * the concavity to the belly is one: moved in, it ties the two by a web that no later cut
    * undoes); the vertex stays pinched then, and the surface is split there
    * (splitSolidPinches()). */
  std::uint32_t partToMove (StarScratch& s, const Parts& parts) const
  {
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t p = 0; p < parts.side.size (); ++p)
      if (parts.movable[p] && parts.count[parts.side[p]] > 1 && !trapsACorner (members (s, parts, p), s))
        candidates.push_back (p);
    std::stable_sort (candidates.begin (), candidates.end (),
                      [&] (std::uint32_t p, std::uint32_t q) { return parts.weight[p] < parts.weight[q]; });
    return firstMakingNoHandle (
        candidates, [&] (std::uint32_t p) { return members (s, parts, p); }, s, Fallback::making_one_handle);
  }

  /** Would moving out \a move, inside tetrahedra of the star that \a s holds, leave a corner of
    * it other than the star's vertex floating (its star all outside) with no tetrahedron of its
    * star that the mending of a floating point could move in (bringsOn(), next to an inside
    * one)? A point in a flat pocket of four tetrahedra whose neighbours across the pocket are all
    * outside is so trapped once its last inside tetrahedron moves out. (In a volume, whose solid
    * is X's, a pair of tetrahedra may move to bring a point on.) A tetrahedron across a corner's
    * star with a vertex outside the block being mended may be moving on another thread: it counts
    * as a way on, so that the answer depends on the blocks alone. */
  bool trapsACorner (const std::vector<std::uint32_t>& move, StarScratch& s) const
  {
    if (!stays_buried_.empty () || !inside (move.front ()))
      return false;
    const auto moved = [&] (std::uint32_t t) { return std::find (move.begin (), move.end (), t) != move.end (); };
    const auto inside_after = [&] (std::uint32_t t) { return inside (t) && !moved (t); };
    for (std::uint32_t u : tetrahedra_.verticesOf (move))
    {
      if (u == s.star.vertex () || labels_.isApart (u))
        continue;
      tetrahedra_.gatherStar (u, s.corner);
      const auto& star = s.corner.tetrahedra ();
      if (std::any_of (star.begin (), star.end (), inside_after))
        continue; // not floating
      const bool rescued = std::any_of (star.begin (), star.end (), [&] (std::uint32_t c) {
        return !moved (c) && bringsOn (c, [&] (std::uint32_t across) {
          return across != OUTSIDE_HULL && (!within (across, s.lo, s.hi) || inside_after (across));
        });
      });
      if (!rescued)
        return true;
    }
    return false;
  }

  /** What firstMakingNoHandle() takes when every candidate makes a handle. */
  enum class Fallback
  {
    weakest,          ///< the first of all, or the only one, unweighed
    making_one_handle ///< the first that makes exactly one; none if each makes several
  };

  /** The first of \a candidates (weakest first) whose move, the tetrahedra \a moved gives, makes no
    * handle; else as \a fallback says; in a volume (whose solid is X's) the first of all; NONE if
    * there is none. */
  template <class Moved>
  std::uint32_t firstMakingNoHandle (const std::vector<std::uint32_t>& candidates, const Moved& moved, StarScratch& s,
                                     Fallback fallback = Fallback::weakest) const
  {
    if (candidates.empty ())
      return NONE;
    if (!stays_buried_.empty () || (fallback == Fallback::weakest && candidates.size () == 1))
      return candidates.front ();
    std::uint32_t making_one = NONE;
    for (std::uint32_t c : candidates)
    {
      const int change = (*euler_change_) (moved (c), s.euler);
      if (change >= 0)
        return c;
      if (change == -1 && making_one == NONE)
        making_one = c;
    }
    return fallback == Fallback::weakest ? candidates.front () : making_one;
  }

  static std::vector<std::uint32_t> members (const StarScratch& s, const Parts& parts, std::uint32_t p)
  {
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < s.star.size (); ++k)
      if (parts.part[k] == p)
        out.push_back (s.star[k]);
    return out;
  }

  /** The link of the vertex whose star \a s holds in the surface, into s.link: per surface
    * triangle at it (counted from its inside tetrahedron), the edge opposite the vertex. */
  void gatherSurfaceLink (StarScratch& s) const
  {
    const std::uint32_t v = s.star.vertex ();
    s.link.clear ();
    for (std::uint32_t t : s.star.tetrahedra ())
      for (int i = 0; inside (t) && i < 4; ++i)
        if (tetrahedra_.vertex (t, i) != v && !inside (tetrahedra_.neighbour (t, i)))
        {
          LinkEdge edge{};
          for (int j = 0, k = 0; j < 4; ++j)
            if (j != i && tetrahedra_.vertex (t, j) != v)
              edge[k++] = tetrahedra_.vertex (t, j);
          s.link.push_back (edge);
        }
  }

  /** Do the surface triangles around the vertex whose star \a s holds make one fan, as on a
    * 2-manifold (surfaceVerticesToMend()'s test)? Then its star has one part on each side, and
    * mendVertex() has nothing to do. */
  bool oneFan (StarScratch& s) const
  {
    gatherSurfaceLink (s);
    return isOneCycle (s.link.begin (), s.link.end ());
  }

  /** An edge (v, w) of the gathered star of v with more than two surface triangles: w, or NONE.
    * Its link edges meet at w more than twice. */
  std::uint32_t pinchedEdge (StarScratch& s) const
  {
    gatherSurfaceLink (s);
    s.edge_uses.clear ();
    for (const LinkEdge& edge : s.link)
      s.edge_uses.insert (s.edge_uses.end (), edge.begin (), edge.end ());
    std::sort (s.edge_uses.begin (), s.edge_uses.end ());
    for (std::size_t a = 0; a < s.edge_uses.size ();)
    {
      std::size_t b = a;
      while (b < s.edge_uses.size () && s.edge_uses[b] == s.edge_uses[a])
        ++b;
      if (b - a > 2)
        return s.edge_uses[a];
      a = b;
    }
    return NONE;
  }

  /** The tetrahedra to move at the vertex whose star \a s holds (empty: nothing to mend, or
    * nothing allowed); \a pinched: the surface touches itself there (a pinched edge, or more than
    * one fan). */
  std::vector<std::uint32_t> mendVertex (StarScratch& s, bool& pinched) const
  {
    const std::uint32_t v = s.star.vertex ();
    if (s.star.empty ())
      return {};
    // A pinched edge first: its ring's parts, joined only across facets that hold the edge.
    const std::uint32_t w = pinchedEdge (s);
    if (w != NONE)
    {
      const Parts ring = split (s, [&] (int k) { return tetrahedra_.hasVertex (s.star[k], w); },
                                [&] (std::uint32_t t, int i) { return tetrahedra_.vertex (t, i) != w; });
      const std::uint32_t p = partToMove (s, ring);
      if (p != NONE)
        return members (s, ring, p);
    }
    const Parts parts = split (s, [] (int) { return true; });
    pinched = w != NONE || parts.count[0] + parts.count[1] > 2;
    if (parts.count[0] + parts.count[1] > 2)
    {
      const std::uint32_t p = partToMove (s, parts);
      if (p != NONE)
        return members (s, parts, p);
      return {};
    }
    if (labels_.isApart (v))
      return {}; // no surface the points show passes through it
    if ((parts.count[0] == 0 && !staysBuried (v)) || parts.count[1] == 0)
    {
      // Buried or floating: move the weakest tetrahedron of the star that touches the other side;
      // in a volume, when none does (a point on a fin of X), the weakest such pair of a star
      // tetrahedron and its neighbour.
      const bool buried = parts.count[0] == 0;
      const auto other_side = [&] (std::uint32_t u) { return buried ? !inside (u) : inside (u); };
      const auto touches = [&] (std::uint32_t t) {
        for (int i = 0; i < 4; ++i)
          if (other_side (tetrahedra_.neighbour (t, i)))
            return true;
        return false;
      };
      // The weakest that makes no handle, if any; in a volume, whose inside is X's, the weakest.
      // Last, those SPIKE_LENGTH times longer than the shortest: from a point in a fold, they
      // reach across the object.
      std::vector<std::pair<std::uint32_t, double>> touching; // (tetrahedron, its longest edge)
      double shortest = std::numeric_limits<double>::infinity ();
      for (std::uint32_t t : s.star.tetrahedra ())
        if (bringsOn (t, other_side))
        {
          touching.emplace_back (t, longestEdge (tetrahedra_, positions_, t));
          shortest = std::min (shortest, touching.back ().second);
        }
      std::vector<std::uint32_t> candidates, spikes;
      for (const auto& [t, longest] : touching)
        (longest > SPIKE_LENGTH * shortest ? spikes : candidates).push_back (t);
      const auto weakest_first = [&] (std::uint32_t t, std::uint32_t u) {
        return labels_.margin[t] != labels_.margin[u] ? labels_.margin[t] < labels_.margin[u] : t < u;
      };
      std::sort (candidates.begin (), candidates.end (), weakest_first);
      std::sort (spikes.begin (), spikes.end (), weakest_first);
      candidates.insert (candidates.end (), spikes.begin (), spikes.end ());
      const std::uint32_t best = firstMakingNoHandle (
          candidates, [] (std::uint32_t t) { return std::vector<std::uint32_t>{t}; }, s);
      if (best != NONE)
        return {best};
      if (stays_buried_.empty ()) // not a volume
        return {};
      std::array<std::uint32_t, 2> pair{NONE, NONE};
      double weakest_pair = 0;
      for (std::uint32_t t : s.star.tetrahedra ())
        for (int i = 0; i < 4 && !flipped_[t]; ++i)
        {
          const std::uint32_t u = tetrahedra_.neighbour (t, i);
          if (u == OUTSIDE_HULL || flipped_[u] || inside (u) != inside (t) || !touches (u))
            continue;
          const double margin = double (labels_.margin[t]) + labels_.margin[u];
          if (pair[0] == NONE || margin < weakest_pair)
          {
            pair = {t, u};
            weakest_pair = margin;
          }
        }
      if (pair[0] != NONE)
        return {pair[0], pair[1]};
    }
    return {};
  }

  const Tetrahedra& tetrahedra_;
  const SimplicialComplex& complex_;
  const std::vector<Point3>& positions_;
  SolidLabels& labels_;
  std::vector<std::uint8_t> stays_buried_; // per vertex, with keep_buried; else empty
  std::vector<std::uint8_t> flipped_;
  std::vector<std::uint8_t> unmended_; // per vertex: left pinched when last looked at
  std::vector<std::uint32_t> hull_hops_;         // hullHops(), for one search for handles
  std::vector<double> spacing_at_;               // per vertex: spacingAt(), NaN until a gap check needs it
  std::vector<double> spacing_around_;           // per vertex: spacingAround(), NaN until needed
  Star neighbour_star_;                          // spacingAround()'s scratch
  std::optional<SolidEulerChange> euler_change_; // from the first mending on
};

} // namespace

SolidRepair
repairSolid (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
             SolidLabels& labels, bool keep_buried)
{
  if (tetrahedra.complex ().dimension () != 3)
    return {};
  return Repairer (tetrahedra, positions, labels, keep_buried).run (x);
}

} // namespace pcl_wrap::detail
