// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_join.h"

#include "util/distance.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"
#include "util/union_find.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <queue>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** How many tetrahedra bringFloatingPointsOn() expands from a point, at most: a path of X's
  * tetrahedra that reaches no further ends in a stray point's own few tetrahedra. */
constexpr std::size_t FLOATING_REACH = 256;

/** The points a join would tie together, and how far apart they are. */
class JoinGaps
{
public:
  JoinGaps (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const std::vector<std::uint32_t>& part)
    : tetrahedra_ (tetrahedra), positions_ (positions), part_ (part)
  {}

  /** Is the gap between part \a p and part \a q along the tetrahedra of \a chain no wider than
    * UNRESOLVED_GAP spacings: some vertex of p on the chain as near some other vertex of q on it,
    * in units of the smaller of their spacings (spacingAt())? A vertex on both is no such pair:
    * the labelling can put inside a tetrahedron from one object's surface to a point of another,
    * across a gap the sampling resolves, and the two parts then share that point. */
  bool unresolved (const std::vector<std::uint32_t>& chain, std::uint32_t p, std::uint32_t q)
  {
    const std::vector<std::uint32_t> corners = tetrahedra_.verticesOf (chain);
    std::vector<std::pair<std::uint32_t, double>> on_p, on_q; // (vertex, its spacing)
    for (std::uint32_t v : corners)
    {
      // One look at v's star: whether it is on p or q, and its shortest Delaunay edge.
      tetrahedra_.gatherStar (v, star_);
      bool in_p = false, in_q = false;
      for (std::uint32_t t : star_.tetrahedra ())
      {
        in_p = in_p || part_[t] == p;
        in_q = in_q || part_[t] == q;
      }
      const double spacing = in_p || in_q ? spacingAt (tetrahedra_, star_, v, positions_) : 0.0;
      if (in_p)
        on_p.emplace_back (v, spacing);
      if (in_q)
        on_q.emplace_back (v, spacing);
    }
    for (const auto& [a, spacing_a] : on_p)
      for (const auto& [b, spacing_b] : on_q)
        if (a != b && !resolvedGap (positions_[a], positions_[b], spacing_a, spacing_b))
          return true;
    return false;
  }

private:
  const Tetrahedra& tetrahedra_;
  const std::vector<Point3>& positions_;
  const std::vector<std::uint32_t>& part_;
  Star star_;
};

/** Is tetrahedron \a t in X, or one of its triangles? */
bool
inX (const Tetrahedra& tetrahedra, const Subcomplex& x, std::uint32_t t)
{
  if (x.contains ({3, t}))
    return true;
  for (int i = 0; i < 4; ++i)
    if (x.contains (tetrahedra.complex ().facet (3, t, i)))
      return true;
  return false;
}

/** Cheapest paths of outside tetrahedra to the solid, by the cost that run() is given: one search
  * at a time, from seeds, in scratch arrays that each search leaves as it found them. */
class CheapestPaths
{
public:
  static constexpr std::uint32_t NONE = SolidParts::NO_PART;

  // cost_ and from_ are written only where a search reaches (is_reached_): searches are local, and
  // the pages of the rest of these arrays, as large as the mesh, are never touched.
  CheapestPaths (const Tetrahedra& tetrahedra, const SolidLabels& labels)
    : tetrahedra_ (tetrahedra),
      labels_ (labels),
      cost_ (new double[tetrahedra.size ()]),
      from_ (new std::uint32_t[tetrahedra.size ()]),
      is_reached_ (tetrahedra.size (), false)
  {}

  void seed (std::uint32_t t, double cost)
  {
    reach (t, cost, NONE);
    queue_.push ({cost, t});
  }

  /** Searches from the seeds through the outside tetrahedra that \a passable admits, cheapest
    * first, and stops at the first facet from a tetrahedron a it reached to an inside one b that
    * \a accept (a, b) takes, or after expanding \a limit tetrahedra. A path's cost is \a step
    * (c, b) where it goes on to b from a path of cost c; it must not fall. Returns a (NONE if
    * none): trace() gives the path to it, cost() its cost. */
  template <class Passable, class Accept, class Step>
  std::uint32_t run (const Passable& passable, const Accept& accept, std::size_t limit, const Step& step)
  {
    for (std::size_t expanded = 0; !queue_.empty () && expanded < limit;)
    {
      const auto [c, a] = queue_.top ();
      queue_.pop ();
      if (c > cost_[a]) // a was reached, by a cheaper path since
        continue;
      ++expanded;
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t b = tetrahedra_.neighbour (a, i);
        if (b == OUTSIDE_HULL)
          continue;
        if (labels_.inside[b])
        {
          if (accept (a, b))
            return a;
          continue;
        }
        const double through = step (c, b);
        if (through >= cost (b) || !passable (b))
          continue;
        reach (b, through, a);
        queue_.push ({through, b});
      }
    }
    return NONE;
  }

  /** The path the search took to \a a, from a back to its seed. */
  std::vector<std::uint32_t> trace (std::uint32_t a) const
  {
    std::vector<std::uint32_t> path;
    for (std::uint32_t t = a; t != NONE; t = from_[t])
      path.push_back (t);
    return path;
  }

  /** The cost of the cheapest path found to \a t (infinite if none). */
  double cost (std::uint32_t t) const { return is_reached_[t] ? cost_[t] : std::numeric_limits<double>::infinity (); }

  /** Leaves the scratch arrays as they were before the seeds. */
  void clear ()
  {
    for (std::uint32_t t : reached_)
      is_reached_[t] = false;
    reached_.clear ();
    queue_ = {};
  }

private:
  using Entry = std::pair<double, std::uint32_t>;

  void reach (std::uint32_t t, double cost, std::uint32_t from)
  {
    if (!is_reached_[t])
    {
      is_reached_[t] = true;
      reached_.push_back (t);
    }
    cost_[t] = cost;
    from_[t] = from;
  }

  const Tetrahedra& tetrahedra_;
  const SolidLabels& labels_;
  std::unique_ptr<double[]> cost_;
  std::unique_ptr<std::uint32_t[]> from_;
  std::vector<bool> is_reached_;
  std::vector<std::uint32_t> reached_;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue_;
};

/** The step of CheapestPaths::run() for a path's cost by summed margins: how strongly the labelling
  * put its tetrahedra outside. */
auto
summedMargins (const SolidLabels& labels)
{
  return [&labels] (double c, std::uint32_t t) { return c + labels.margin[t]; };
}

/** The step of CheapestPaths::run() for a path's cost by its longest edge. */
auto
longestEdgeOnPath (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions)
{
  return [&tetrahedra, &positions] (double c, std::uint32_t t) {
    return std::max (c, longestEdge (tetrahedra, positions, t));
  };
}

/** Moves the outside tetrahedra of \a path inside. */
void
moveInside (const std::vector<std::uint32_t>& path, SolidLabels& labels, std::vector<std::uint8_t>& moved_flags,
            std::vector<std::uint32_t>& moved)
{
  for (std::uint32_t t : path)
    if (!labels.inside[t])
    {
      labels.inside[t] = 1;
      moved_flags[t] = 1;
      moved.push_back (t);
    }
}

/** Does part \a p, whose vertices are \a corners, hold one of them on no other part's tetrahedra? */
bool
holdsAPointAlone (const Tetrahedra& tetrahedra, const std::vector<std::uint32_t>& part, std::uint32_t p,
                  const std::vector<std::uint32_t>& corners)
{
  Star star;
  return std::any_of (corners.begin (), corners.end (), [&] (std::uint32_t v) {
    tetrahedra.gatherStar (v, star);
    return std::all_of (star.tetrahedra ().begin (), star.tetrahedra ().end (),
                        [&] (std::uint32_t t) { return part[t] == SolidParts::NO_PART || part[t] == p; });
  });
}

/** A fragment that X ties to the rest by edges alone (a few noisy points beside the surface) is
  * joined by any outside tetrahedra of its points' group: of the paths to a part that \a accept
  * takes whose longest edge is the shortest, the cheapest by summed margins, each search within
  * FLOATING_REACH tetrahedra (the first path, if the second search does not get so far). Returns
  * the path, from its end back to the fragment (none if there is none). With \a moves, the
  * tetrahedra of \a fragment are outside ones that the path moves too (a floating point's star),
  * and count as its others do. */
template <class Accept>
std::vector<std::uint32_t>
nearestJoin (CheapestPaths& paths, const std::vector<std::uint32_t>& fragment, const Accept& accept,
             const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const SolidLabels& labels,
             bool moves = false)
{
  const auto in_group = [&] (std::uint32_t t) { return labels.mayGoInside (tetrahedra.vertices (t)); };
  for (std::uint32_t t : fragment)
    if (!moves || in_group (t))
      paths.seed (t, moves ? longestEdge (tetrahedra, positions, t) : 0.0);
  const std::uint32_t shortest =
      paths.run (in_group, accept, FLOATING_REACH, longestEdgeOnPath (tetrahedra, positions));
  if (shortest == CheapestPaths::NONE)
    return {};
  std::vector<std::uint32_t> path = paths.trace (shortest);
  const double bottleneck = paths.cost (shortest);
  paths.clear ();
  const auto no_longer = [&] (std::uint32_t t) {
    return in_group (t) && longestEdge (tetrahedra, positions, t) <= bottleneck;
  };
  for (std::uint32_t t : fragment)
    if (!moves || no_longer (t))
      paths.seed (t, moves ? double (labels.margin[t]) : 0.0);
  const std::uint32_t cheapest = paths.run (no_longer, accept, FLOATING_REACH, summedMargins (labels));
  if (cheapest != CheapestPaths::NONE)
    path = paths.trace (cheapest);
  return path;
}

} // namespace

bool
resolvedGap (const Point3& a, const Point3& b, double spacing_a, double spacing_b, double gap)
{
  return distance (a, b) > gap * std::min (spacing_a, spacing_b);
}

double
longestEdge (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, std::uint32_t t)
{
  const std::uint32_t* v = tetrahedra.vertices (t);
  double longest = 0.0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      longest = std::max (longest, distance (positions[v[i]], positions[v[j]]));
  return longest;
}

double
spacingAt (const Tetrahedra& tetrahedra, const Star& star, std::uint32_t v, const std::vector<Point3>& positions)
{
  double spacing = std::numeric_limits<double>::infinity ();
  for (std::uint32_t t : star.tetrahedra ())
    for (int i = 0; i < 4; ++i)
      if (tetrahedra.vertex (t, i) != v)
        spacing = std::min (spacing, distance (positions[v], positions[tetrahedra.vertex (t, i)]));
  return spacing;
}

double
spacingAround (const Tetrahedra& tetrahedra, const Star& star, std::uint32_t v, const std::vector<Point3>& positions,
               std::vector<double>& known, Star& scratch)
{
  std::vector<double> spacings;
  for (std::uint32_t w : tetrahedra.verticesOf (star.tetrahedra ())) // v among them
  {
    if (std::isnan (known[w]))
    {
      const Star* around = &star;
      if (w != v)
      {
        tetrahedra.gatherStar (w, scratch);
        around = &scratch;
      }
      known[w] = spacingAt (tetrahedra, *around, w, positions);
    }
    spacings.push_back (known[w]);
  }
  const auto middle = spacings.begin () + spacings.size () / 2;
  std::nth_element (spacings.begin (), middle, spacings.end ());
  return *middle;
}

SolidJoin
joinPartsThroughX (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                   const SolidParts& parts, SolidLabels& labels, std::vector<std::uint8_t>& moved_flags)
{
  constexpr std::uint32_t NONE = SolidParts::NO_PART;
  const std::size_t n = tetrahedra.size ();
  const std::vector<std::uint32_t>& part = parts.part;
  SolidJoin join;
  join.parts = parts.size.size ();
  if (join.parts < 2)
    return join;
  UnionFind joined (parts.size.size ());
  std::vector<std::uint32_t> order (parts.size.size ());
  std::iota (order.begin (), order.end (), 0u);
  std::stable_sort (order.begin (), order.end (),
                    [&] (std::uint32_t a, std::uint32_t b) { return parts.size[a] < parts.size[b]; });
  const std::uint32_t largest = order.back ();
  order.pop_back (); // the largest part stays as it is, and needs no list of its members
  std::vector<std::vector<std::uint32_t>> members (parts.size.size ());
  for (std::uint32_t t : indicesWhere (n, [&] (std::size_t t) { return part[t] != NONE && part[t] != largest; }))
    members[part[t]].push_back (t);
  JoinGaps gaps (tetrahedra, positions, part);
  CheapestPaths paths (tetrahedra, labels);
  std::vector<std::uint8_t> on_part (tetrahedra.complex ().numVertices (), 0);
  for (std::uint32_t p : order)
  {
    const std::uint32_t mine = joined.find (p);
    const std::vector<std::uint32_t> corners = tetrahedra.verticesOf (members[p]);
    const bool fragment = corners.size () < FRAGMENT_VERTICES;
    // A part of its own may only close a gap at its surface: its search stays among the
    // tetrahedra that touch it. Neither crosses the gap between two groups of the sample: a
    // fragment of a blob beside an object is no tip cut off it.
    for (std::uint32_t v : corners)
      on_part[v] = !fragment;
    const auto passable = [&] (std::uint32_t t) {
      const std::uint32_t* v = tetrahedra.vertices (t);
      return inX (tetrahedra, x, t) && labels.oneGroup (v) &&
             (fragment || on_part[v[0]] || on_part[v[1]] || on_part[v[2]] || on_part[v[3]]);
    };
    // A fragment joins the part it reaches first; a part of its own only one it was cut from,
    // across a gap the sampling does not resolve.
    std::uint32_t goal = NONE;
    const auto accept = [&] (std::uint32_t a, std::uint32_t b) {
      if (part[b] == NONE || joined.find (part[b]) == mine)
        return false;
      std::vector<std::uint32_t> chain = paths.trace (a);
      chain.push_back (b);
      if (!fragment && !gaps.unresolved (chain, p, part[b]))
        return false;
      goal = part[b];
      return true;
    };
    for (std::uint32_t t : members[p])
      paths.seed (t, 0);
    const std::uint32_t end = paths.run (passable, accept, n, summedMargins (labels));
    std::vector<std::uint32_t> path;
    if (end != NONE)
      path = paths.trace (end);
    else if (fragment && holdsAPointAlone (tetrahedra, part, p, corners))
    {
      paths.clear ();
      path = nearestJoin (paths, members[p], accept, tetrahedra, positions, labels);
    }
    if (!path.empty ())
    {
      joined.attach (mine, goal);
      --join.parts;
      moveInside (path, labels, moved_flags, join.moved);
    }
    paths.clear ();
    for (std::uint32_t v : corners)
      on_part[v] = 0;
  }
  return join;
}

std::vector<std::uint32_t>
bringFloatingPointsOn (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                       SolidLabels& labels, std::vector<std::uint8_t>& moved_flags)
{
  constexpr std::uint32_t NONE = CheapestPaths::NONE;
  const std::uint32_t num_vertices = tetrahedra.complex ().numVertices ();
  std::vector<std::uint8_t> on_solid (num_vertices, 0);
  const auto markOn = [&] (std::uint32_t t) { // also from several threads at once
    for (int i = 0; i < 4; ++i)
      relaxedStore (&on_solid[tetrahedra.vertex (t, i)], std::uint8_t (1));
  };
  parallelForEach (tetrahedra.size (), [&] (std::size_t t) {
    if (labels.inside[t])
      markOn (static_cast<std::uint32_t> (t));
  });
  std::vector<std::uint32_t> moved;
  CheapestPaths paths (tetrahedra, labels);
  const auto in_x = [&] (std::uint32_t t) {
    return inX (tetrahedra, x, t) && labels.oneGroup (tetrahedra.vertices (t));
  };
  const auto accept = [] (std::uint32_t, std::uint32_t) { return true; };
  const auto longest_edge = [&] (std::uint32_t t) { return longestEdge (tetrahedra, positions, t); };
  const auto touches_solid = [&] (std::uint32_t t) {
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      if (u != OUTSIDE_HULL && labels.inside[u])
        return true;
    }
    return false;
  };
  // Would moving the outside tetrahedra of path inside leave one of their corners with no outside
  // tetrahedron around it (nor the hull)? The mending could not bring it back through them.
  Star around;
  const auto buries = [&] (const std::vector<std::uint32_t>& path) {
    for (std::uint32_t u : tetrahedra.verticesOf (path))
    {
      tetrahedra.gatherStar (u, around);
      const bool open = std::any_of (around.tetrahedra ().begin (), around.tetrahedra ().end (), [&] (std::uint32_t t) {
        if (std::find (path.begin (), path.end (), t) != path.end ())
          return false;
        if (!labels.inside[t])
          return true;
        for (int i = 0; i < 4; ++i)
          if (tetrahedra.vertex (t, i) != u && tetrahedra.neighbour (t, i) == OUTSIDE_HULL)
            return true; // u is on a hull facet of t
        return false;
      });
      if (!open)
        return true;
    }
    return false;
  };
  Star star;
  for (std::uint32_t v = 0; v < num_vertices; ++v)
  {
    if (on_solid[v] || labels.isApart (v))
      continue;
    tetrahedra.gatherStar (v, star);
    // The way the point comes on otherwise: a tetrahedron of its star that touches the solid,
    // moved by the mending (within one group of the sample), or else X's cheapest path to the
    // solid.
    double usual = std::numeric_limits<double>::infinity ();
    for (std::uint32_t t : star.tetrahedra ())
      if (touches_solid (t) && labels.oneGroup (tetrahedra.vertices (t)))
        usual = std::min (usual, longest_edge (t));
    std::vector<std::uint32_t> path;
    if (usual == std::numeric_limits<double>::infinity ())
    {
      for (std::uint32_t t : star.tetrahedra ())
        if (in_x (t))
          paths.seed (t, labels.margin[t]);
      const std::uint32_t end = paths.run (in_x, accept, FLOATING_REACH, summedMargins (labels));
      if (end != NONE)
        path = paths.trace (end);
      paths.clear ();
      if (path.empty () && !labels.group.empty ())
      {
        // No tetrahedron of X around the point either: W holds it by a sheet across the gap
        // between its group and another (a blob's point facing an object). It comes on as a
        // fragment of its group does, through any tetrahedra of the group (nearestJoin()).
        path = nearestJoin (paths, star.tetrahedra (), accept, tetrahedra, positions, labels, true);
        paths.clear ();
      }
      if (!path.empty ())
      {
        usual = 0.0;
        for (std::uint32_t t : path)
          usual = std::max (usual, longest_edge (t));
      }
    }
    // Where the solid beside the point is a fold or a crease away, that way can be a spike across
    // the object: a path of X's much shorter tetrahedra (the shortest longest edge first) is
    // taken instead. Only tetrahedra short enough are searched: in a noisy layer, none.
    if (usual < std::numeric_limits<double>::infinity ())
    {
      const auto short_in_x = [&] (std::uint32_t t) { return in_x (t) && SPIKE_LENGTH * longest_edge (t) < usual; };
      for (std::uint32_t t : star.tetrahedra ())
        if (short_in_x (t))
          paths.seed (t, longest_edge (t));
      const std::uint32_t end =
          paths.run (short_in_x, accept, FLOATING_REACH, longestEdgeOnPath (tetrahedra, positions));
      if (end != NONE)
      {
        std::vector<std::uint32_t> shorter = paths.trace (end);
        if (!buries (shorter))
          path = std::move (shorter);
      }
      paths.clear ();
    }
    moveInside (path, labels, moved_flags, moved);
    for (std::uint32_t t : path)
      markOn (t);
  }
  return moved;
}

} // namespace pcl_wrap::detail
