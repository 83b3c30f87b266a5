// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "solid_repair.h"

#include "regular_triangulation.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <queue>
#include <vector>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t OUTSIDE_HULL = NO_NEIGHBOUR; // beyond the convex hull: outside for good

/** The tetrahedra around one vertex (its star), or around one edge (its ring), and how they split
  * into connected parts on each side of the surface. */
class Repairer
{
public:
  Repairer (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, SolidLabels& labels)
    : complex_ (complex), neighbours_ (neighbours), labels_ (labels), seen_ (complex.size (3), 0), slot_ (complex.size (3)),
      flipped_ (complex.size (3), 0), tet_of_vertex_ (complex.numVertices (), NO_NEIGHBOUR)
  {
    for (SimplexId t = 0; t < complex.size (3); ++t)
      for (int i = 0; i < 4; ++i)
        tet_of_vertex_[complex.vertex (3, t, i)] = t;
  }

  SolidRepair run (const Retraction& x)
  {
    SolidRepair done;
    std::vector<std::uint32_t> all (complex_.numVertices ());
    std::iota (all.rbegin (), all.rend (), 0u); // popped from the back: vertex 0 first
    mend (all, done);
    const std::vector<std::uint32_t> joined = join (x);
    done.flipped += joined.size ();
    std::vector<std::uint32_t> touched;
    for (std::uint32_t t : joined)
      for (int i = 0; i < 4; ++i)
        touched.push_back (complex_.vertex (3, t, i));
    std::sort (touched.rbegin (), touched.rend ());
    touched.erase (std::unique (touched.begin (), touched.end ()), touched.end ());
    mend (touched, done);
    return done;
  }

private:
  /** Mends the vertices of \a work (popped from the back) and those of every tetrahedron moved. */
  void mend (std::vector<std::uint32_t> work, SolidRepair& done)
  {
    std::vector<std::uint8_t> queued (complex_.numVertices (), 0);
    for (std::uint32_t v : work)
      queued[v] = 1;
    while (!work.empty ())
    {
      const std::uint32_t v = work.back ();
      work.pop_back ();
      queued[v] = 0;
      const std::vector<std::uint32_t> flips = mendVertex (v);
      for (std::uint32_t t : flips)
      {
        labels_.inside[t] ^= 1u;
        flipped_[t] = 1;
        ++done.flipped;
        for (int i = 0; i < 4; ++i)
        {
          const std::uint32_t u = complex_.vertex (3, t, i);
          if (!queued[u])
          {
            queued[u] = 1;
            work.push_back (u);
          }
        }
      }
    }
  }

  /** Is tetrahedron \a t in X, or one of its triangles (a sheet of X, where the retraction
    * thinned a part of the solid to zero thickness)? */
  bool inX (const Retraction& x, std::uint32_t t) const
  {
    if (x.inY ({3, t}))
      return true;
    for (int i = 0; i < 4; ++i)
      if (x.inY (complex_.facet (3, t, i)))
        return true;
    return false;
  }

  /** Joins the connected parts of the solid that X's tetrahedra join: from each part but the
    * largest, smallest first, the cheapest path (by summed margins) of outside tetrahedra of X
    * to another part moves inside. X is contractible, so a part cut off the solid by the labelling
    * (a thin leg, a horn) is tied to the rest through X; separate objects are not, as X joins them
    * through lower-dimensional simplices only. Returns the tetrahedra moved. */
  std::vector<std::uint32_t> join (const Retraction& x)
  {
    const std::size_t n = complex_.size (3);
    std::vector<std::uint32_t> part (n, NO_NEIGHBOUR);
    std::vector<std::uint32_t> size_of;
    for (std::uint32_t t = 0; t < n; ++t)
    {
      if (!labels_.inside[t] || part[t] != NO_NEIGHBOUR)
        continue;
      const auto p = static_cast<std::uint32_t> (size_of.size ());
      size_of.push_back (0);
      std::vector<std::uint32_t> stack{t};
      part[t] = p;
      while (!stack.empty ())
      {
        const std::uint32_t a = stack.back ();
        stack.pop_back ();
        ++size_of[p];
        for (int i = 0; i < 4; ++i)
        {
          const std::uint32_t b = neighbours_[4 * std::size_t (a) + i];
          if (b != OUTSIDE_HULL && labels_.inside[b] && part[b] == NO_NEIGHBOUR)
          {
            part[b] = p;
            stack.push_back (b);
          }
        }
      }
    }
    std::vector<std::uint32_t> moved;
    if (size_of.size () < 2)
      return moved;
    std::vector<std::uint32_t> root (size_of.size ());
    std::iota (root.begin (), root.end (), 0u);
    const auto find = [&] (std::uint32_t a) {
      while (root[a] != a)
        a = root[a] = root[root[a]];
      return a;
    };
    std::vector<std::uint32_t> order (size_of.size ());
    std::iota (order.begin (), order.end (), 0u);
    std::stable_sort (order.begin (), order.end (), [&] (std::uint32_t a, std::uint32_t b) { return size_of[a] < size_of[b]; });
    order.pop_back (); // the largest part stays as it is
    std::vector<std::vector<std::uint32_t>> members (size_of.size ());
    for (std::uint32_t t = 0; t < n; ++t)
      if (part[t] != NO_NEIGHBOUR)
        members[part[t]].push_back (t);
    std::vector<double> cost (n, std::numeric_limits<double>::infinity ());
    std::vector<std::uint32_t> from (n, NO_NEIGHBOUR), reached;
    using Entry = std::pair<double, std::uint32_t>;
    for (std::uint32_t p : order)
    {
      const std::uint32_t mine = find (p);
      std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
      for (std::uint32_t t : members[p])
      {
        cost[t] = 0;
        reached.push_back (t);
        queue.push ({0.0, t});
      }
      std::uint32_t goal = NO_NEIGHBOUR;
      while (!queue.empty () && goal == NO_NEIGHBOUR)
      {
        const auto [c, a] = queue.top ();
        queue.pop ();
        if (c > cost[a])
          continue;
        for (int i = 0; i < 4 && goal == NO_NEIGHBOUR; ++i)
        {
          const std::uint32_t b = neighbours_[4 * std::size_t (a) + i];
          if (b == OUTSIDE_HULL)
            continue;
          if (labels_.inside[b])
          {
            if (part[b] != NO_NEIGHBOUR && find (part[b]) != mine)
            {
              goal = b;
              from[b] = a;
            }
            continue;
          }
          const double through = c + labels_.margin[b];
          if (!inX (x, b) || through >= cost[b])
            continue;
          if (cost[b] == std::numeric_limits<double>::infinity ())
            reached.push_back (b);
          cost[b] = through;
          from[b] = a;
          queue.push ({through, b});
        }
      }
      if (goal != NO_NEIGHBOUR)
      {
        root[mine] = find (part[goal]);
        for (std::uint32_t t = from[goal]; !labels_.inside[t]; t = from[t])
        {
          labels_.inside[t] = 1;
          flipped_[t] = 1;
          moved.push_back (t);
        }
      }
      for (std::uint32_t t : reached)
      {
        cost[t] = std::numeric_limits<double>::infinity ();
        from[t] = NO_NEIGHBOUR;
      }
      reached.clear ();
    }
    return moved;
  }

  /** Connected parts of the gathered tetrahedra: part[k] for star_[k], count per side. */
  struct Parts
  {
    std::vector<std::uint32_t> part;
    std::array<std::size_t, 2> count{}; // [0] outside, [1] inside
    std::vector<std::uint8_t> side;     // per part
    std::vector<double> weight;         // per part: summed margins (infinite beyond the hull)
    std::vector<std::uint8_t> movable;  // per part: no tetrahedron of it moved before
  };

  bool inside (std::uint32_t t) const { return t != OUTSIDE_HULL && labels_.inside[t]; }

  /** star_ := the tetrahedra around vertex v. */
  void gatherStar (std::uint32_t v)
  {
    ++stamp_;
    star_.clear ();
    v_ = v;
    const std::uint32_t first = tet_of_vertex_[v];
    if (first == NO_NEIGHBOUR)
      return;
    star_.push_back (first);
    seen_[first] = stamp_;
    slot_[first] = 0;
    for (std::size_t k = 0; k < star_.size (); ++k)
    {
      const std::uint32_t t = star_[k];
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == v)
          continue; // the facet opposite v does not contain it
        const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
        if (u != OUTSIDE_HULL && seen_[u] != stamp_)
        {
          seen_[u] = stamp_;
          slot_[u] = static_cast<std::uint32_t> (star_.size ());
          star_.push_back (u);
        }
      }
    }
  }

  /** The connected parts, on each side, of the star's tetrahedra for which \a keep (index into
    * star_) holds, joined across facets that contain v and every vertex \a through requires. */
  template <class Keep, class Through = bool (*) (std::uint32_t, int)>
  Parts split (const Keep& keep, const Through& through = [] (std::uint32_t, int) { return true; })
  {
    const std::size_t m = star_.size ();
    std::vector<std::uint32_t>& parent = parent_;
    parent.resize (m + 1);
    std::iota (parent.begin (), parent.end (), 0u);
    const auto find = [&] (std::uint32_t a) {
      while (parent[a] != a)
        a = parent[a] = parent[parent[a]];
      return a;
    };
    const auto local = [&] (std::uint32_t u) { return seen_[u] == stamp_ ? slot_[u] : static_cast<std::uint32_t> (m); };
    bool touches_hull = false;
    for (std::size_t k = 0; k < m; ++k)
    {
      if (!keep (static_cast<int> (k)))
        continue;
      const std::uint32_t t = star_[k];
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == v_ || !through (t, i))
          continue;
        const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
        if (u == OUTSIDE_HULL)
        {
          touches_hull = true;
          if (!inside (t))
            parent[find (static_cast<std::uint32_t> (k))] = find (static_cast<std::uint32_t> (m));
        }
        else if (inside (u) == inside (t) && u > t)
        {
          const std::uint32_t j = local (u);
          if (j < m && keep (static_cast<int> (j)))
            parent[find (static_cast<std::uint32_t> (k))] = find (j);
        }
      }
    }
    Parts parts;
    parts.part.assign (m + 1, NO_NEIGHBOUR);
    std::vector<std::uint32_t>& id_of_root = id_of_root_;
    id_of_root.assign (m + 1, NO_NEIGHBOUR);
    for (std::size_t k = 0; k <= m; ++k)
    {
      if (k == m ? !touches_hull : !keep (static_cast<int> (k)))
        continue;
      const std::uint32_t r = find (static_cast<std::uint32_t> (k));
      if (id_of_root[r] == NO_NEIGHBOUR)
      {
        id_of_root[r] = static_cast<std::uint32_t> (parts.side.size ());
        const std::uint8_t side = k == m ? 0 : inside (star_[k]);
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
        parts.weight[p] += labels_.margin[star_[k]];
        if (flipped_[star_[k]])
          parts.movable[p] = 0;
      }
    }
    return parts;
  }

  /** The weakest movable part whose side has more than one part (moving the only part of a side
    * would take v off the surface); NO_NEIGHBOUR if none. */
  static std::uint32_t weakest (const Parts& parts)
  {
    std::uint32_t best = NO_NEIGHBOUR;
    for (std::uint32_t p = 0; p < parts.side.size (); ++p)
      if (parts.movable[p] && parts.count[parts.side[p]] > 1 &&
          (best == NO_NEIGHBOUR || parts.weight[p] < parts.weight[best]))
        best = p;
    return best;
  }

  std::vector<std::uint32_t> members (const Parts& parts, std::uint32_t p) const
  {
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < star_.size (); ++k)
      if (parts.part[k] == p)
        out.push_back (star_[k]);
    return out;
  }

  bool contains (std::uint32_t t, std::uint32_t vertex) const
  {
    const std::uint32_t* v = complex_.vertices (3, t);
    return v[0] == vertex || v[1] == vertex || v[2] == vertex || v[3] == vertex;
  }

  /** An edge (v, w) of the gathered star with more than two surface triangles: w, or NO_NEIGHBOUR. */
  std::uint32_t pinchedEdge (std::uint32_t v)
  {
    edge_uses_.clear ();
    for (std::uint32_t t : star_)
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == v)
          continue;
        const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
        if (inside (t) == inside (u) || (u != OUTSIDE_HULL && inside (t) == 0))
          continue; // not a surface triangle, or counted from its inside tetrahedron
        for (int j = 0; j < 4; ++j)
        {
          const std::uint32_t w = complex_.vertex (3, t, j);
          if (j != i && w != v)
            edge_uses_.push_back (w);
        }
      }
    std::sort (edge_uses_.begin (), edge_uses_.end ());
    for (std::size_t a = 0; a < edge_uses_.size ();)
    {
      std::size_t b = a;
      while (b < edge_uses_.size () && edge_uses_[b] == edge_uses_[a])
        ++b;
      if (b - a > 2)
        return edge_uses_[a];
      a = b;
    }
    return NO_NEIGHBOUR;
  }

  /** The tetrahedra to move at v (empty: nothing to mend, or nothing allowed). */
  std::vector<std::uint32_t> mendVertex (std::uint32_t v)
  {
    gatherStar (v);
    if (star_.empty ())
      return {};
    // A pinched edge first: its ring's parts, joined only across facets that hold the edge.
    const std::uint32_t w = pinchedEdge (v);
    if (w != NO_NEIGHBOUR)
    {
      const Parts ring = split ([&] (int k) { return contains (star_[k], w); },
                                [&] (std::uint32_t t, int i) { return complex_.vertex (3, t, i) != w; });
      const std::uint32_t p = weakest (ring);
      if (p != NO_NEIGHBOUR)
        return members (ring, p);
    }
    const Parts parts = split ([] (int) { return true; });
    if (parts.count[0] + parts.count[1] > 2)
    {
      const std::uint32_t p = weakest (parts);
      if (p != NO_NEIGHBOUR)
        return members (parts, p);
      return {};
    }
    if (parts.count[0] == 0 || parts.count[1] == 0)
    {
      // Buried or floating: move the weakest tetrahedron of the star that touches the other side.
      const bool buried = parts.count[0] == 0;
      std::uint32_t best = NO_NEIGHBOUR;
      for (std::uint32_t t : star_)
      {
        if (flipped_[t])
          continue;
        bool touches = false;
        for (int i = 0; i < 4 && !touches; ++i)
        {
          const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
          touches = buried ? !inside (u) : inside (u);
        }
        if (touches && (best == NO_NEIGHBOUR || labels_.margin[t] < labels_.margin[best]))
          best = t;
      }
      if (best != NO_NEIGHBOUR)
        return {best};
    }
    return {};
  }

  const SimplicialComplex& complex_;
  const FilledInParallel<std::uint32_t>& neighbours_;
  SolidLabels& labels_;
  std::vector<std::uint32_t> seen_, slot_; // per tetrahedron: gathered at stamp_, at star_[slot_]
  std::uint32_t stamp_ = 0;
  std::vector<std::uint8_t> flipped_;
  std::vector<std::uint32_t> tet_of_vertex_;
  std::vector<std::uint32_t> star_, edge_uses_, parent_, id_of_root_; // reused from star to star
  std::uint32_t v_ = 0;
};

} // namespace

SolidRepair
repairSolid (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, const Retraction& x,
             SolidLabels& labels)
{
  if (complex.dimension () != 3)
    return {};
  return Repairer (complex, neighbours, labels).run (x);
}

} // namespace pcl_wrap::detail
