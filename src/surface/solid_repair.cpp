// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_repair.h"
#include "surface/link_cycle.h"
#include "util/portable.h"

#include "util/parallel_for_each.h"
#include "delaunay/regular_triangulation.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t OUTSIDE_HULL = NO_NEIGHBOUR; // beyond the convex hull: outside for good
constexpr std::uint32_t NONE = NO_NEIGHBOUR;

/** Where each gathered tetrahedron of one star is in the star's list: a small open-addressing
  * table, emptied per star in the time it was filled, so that any number of threads can gather
  * stars at once without a table as large as the mesh. */
class StarSlots
{
public:
  StarSlots () : keys_ (256, NONE), slots_ (256) {}

  void clear ()
  {
    for (std::uint32_t at : used_)
      keys_[at] = NONE;
    used_.clear ();
  }

  std::uint32_t find (std::uint32_t t) const
  {
    for (std::uint32_t at = home (t);; at = (at + 1) & mask ())
      if (keys_[at] == t)
        return slots_[at];
      else if (keys_[at] == NONE)
        return NONE;
  }

  /** Records \a t at \a slot unless it is there already; returns whether it was new. */
  bool insert (std::uint32_t t, std::uint32_t slot)
  {
    if (2 * (used_.size () + 1) > keys_.size ())
      grow ();
    std::uint32_t at = home (t);
    for (; keys_[at] != NONE; at = (at + 1) & mask ())
      if (keys_[at] == t)
        return false;
    keys_[at] = t;
    slots_[at] = slot;
    used_.push_back (at);
    return true;
  }

private:
  std::uint32_t mask () const { return static_cast<std::uint32_t> (keys_.size () - 1); }
  std::uint32_t home (std::uint32_t t) const { return (t * 2654435761u) >> 8 & mask (); }
  void grow ()
  {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> entries;
    for (std::uint32_t at : used_)
      entries.emplace_back (keys_[at], slots_[at]);
    clear ();
    keys_.assign (2 * keys_.size (), NONE);
    slots_.resize (keys_.size ());
    for (const auto& [t, slot] : entries)
      insert (t, slot);
  }

  std::vector<std::uint32_t> keys_, slots_, used_;
};

/** What one thread needs to look at one vertex's star: reused from star to star. */
struct StarScratch
{
  std::vector<std::uint32_t> star, edge_uses, parent, id_of_root;
  StarSlots slot;
  std::uint32_t v = 0;
};

/** The tetrahedra around one vertex (its star), or around one edge (its ring), and how they split
  * into connected parts on each side of the surface. */
class Repairer
{
public:
  Repairer (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, SolidLabels& labels)
    : complex_ (complex), neighbours_ (neighbours), labels_ (labels), flipped_ (complex.size (3), 0),
      unmended_ (complex.numVertices (), 0), tet_of_vertex_ (complex.numVertices (), NONE)
  {
    // Each vertex's highest-numbered tetrahedron, where the gathering of its star starts.
    parallelForEach (complex.size (3), [&] (std::size_t id) {
      const auto t = static_cast<std::uint32_t> (id);
      for (int i = 0; i < 4; ++i)
      {
        std::uint32_t* at = &tet_of_vertex_[complex.vertex (3, t, i)];
        std::uint32_t seen = relaxedLoad (at);
        while ((seen == NONE || seen < t) &&
               !relaxedCompareExchange (at, seen, t))
        {
        }
      }
    });
  }

  SolidRepair run (const Subcomplex& x)
  {
    SolidRepair done;
    // Most vertices need nothing: find the others on all threads, then mend them in order.
    const std::vector<std::uint8_t> needs = surfaceVerticesToMend ();
    std::vector<std::uint32_t> work;
    for (std::uint32_t v = complex_.numVertices (); v-- > 0;)
      if (needs[v])
        work.push_back (v); // popped from the back: the lowest first
    mend (work, done);
    const std::vector<std::uint32_t> joined = join (x);
    done.flipped += joined.size ();
    std::vector<std::uint32_t> touched;
    for (std::uint32_t t : joined)
      for (int i = 0; i < 4; ++i)
        touched.push_back (complex_.vertex (3, t, i));
    std::sort (touched.rbegin (), touched.rend ());
    touched.erase (std::unique (touched.begin (), touched.end ()), touched.end ());
    mend (touched, done);
    for (std::uint32_t v = 0; v < unmended_.size (); ++v)
      if (unmended_[v])
        done.pinched.push_back (v);
    return done;
  }

private:
  using LinkEdge = std::array<std::uint32_t, 2>;

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
            if (!inside (neighbours_[4 * t + i]))
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
      bool pinched = false;
      const std::vector<std::uint32_t> flips = mendVertex (v, scratch_, pinched);
      unmended_[v] = flips.empty () && pinched;
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
  bool inX (const Subcomplex& x, std::uint32_t t) const
  {
    if (x.contains ({3, t}))
      return true;
    for (int i = 0; i < 4; ++i)
      if (x.contains (complex_.facet (3, t, i)))
        return true;
    return false;
  }

  /** Per tetrahedron, the connected part of the solid it is in (NO_NEIGHBOUR outside), numbered
    * in the order of their lowest tetrahedra; \a size_of gets their sizes. On all threads: a
    * union-find whose roots are always their tree's lowest tetrahedron, so the answer does not
    * depend on the order in which the threads link. */
  std::vector<std::uint32_t> solidParts (std::vector<std::uint32_t>& size_of) const
  {
    const std::size_t n = complex_.size (3);
    FilledInParallel<std::uint32_t> root (n);
    parallelForEach (n, [&] (std::size_t t) { root[t] = static_cast<std::uint32_t> (t); });
    const auto find = [&] (std::uint32_t a) {
      for (std::uint32_t up; (up = relaxedLoad (&root[a])) != a;)
      {
        // Path halving: a non-root's entry is only ever read or pointed further up its tree.
        const std::uint32_t above = relaxedLoad (&root[up]);
        if (above != up)
          relaxedStore (&root[a], above);
        a = above;
      }
      return a;
    };
    parallelForEach (n, [&] (std::size_t t) {
      if (!labels_.inside[t])
        return;
      for (int i = 0; i < 4; ++i)
      {
        const std::uint32_t u = neighbours_[4 * t + i];
        if (u == OUTSIDE_HULL || u < t || !labels_.inside[u])
          continue;
        std::uint32_t a = static_cast<std::uint32_t> (t), b = u;
        while (true)
        {
          a = find (a);
          b = find (b);
          if (a == b)
            break;
          if (a > b)
            std::swap (a, b);
          std::uint32_t expected = b; // b is still a root: hang it under the lower a
          if (relaxedCompareExchange (&root[b], expected, a))
            break;
        }
      }
    });
    std::vector<std::uint32_t> part (n, NO_NEIGHBOUR);
    for (std::uint32_t t = 0; t < n; ++t)
      if (labels_.inside[t] && root[t] == t)
      {
        part[t] = static_cast<std::uint32_t> (size_of.size ());
        size_of.push_back (0);
      }
    parallelForEach (n, [&] (std::size_t t) {
      const std::uint32_t r = labels_.inside[t] ? find (static_cast<std::uint32_t> (t)) : NO_NEIGHBOUR;
      if (r != NO_NEIGHBOUR && r != t)
        part[t] = part[r];
    });
    for (std::uint32_t t = 0; t < n; ++t)
      if (part[t] != NO_NEIGHBOUR)
        ++size_of[part[t]];
    return part;
  }

  /** Joins the connected parts of the solid that X's tetrahedra join: from each part but the
    * largest, smallest first, the cheapest path (by summed margins) of outside tetrahedra of X
    * to another part moves inside. X is contractible, so a part cut off the solid by the labelling
    * (a thin leg, a horn) is tied to the rest through X; separate objects are not, as X joins them
    * through lower-dimensional simplices only. Returns the tetrahedra moved. */
  std::vector<std::uint32_t> join (const Subcomplex& x)
  {
    const std::size_t n = complex_.size (3);
    std::vector<std::uint32_t> size_of;
    const std::vector<std::uint32_t> part = solidParts (size_of);
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

  /** Connected parts of the gathered tetrahedra: part[k] for star[k], count per side. */
  struct Parts
  {
    std::vector<std::uint32_t> part;
    std::array<std::size_t, 2> count{}; // [0] outside, [1] inside
    std::vector<std::uint8_t> side;     // per part
    std::vector<double> weight;         // per part: summed margins (infinite beyond the hull)
    std::vector<std::uint8_t> movable;  // per part: no tetrahedron of it moved before
  };

  bool inside (std::uint32_t t) const { return t != OUTSIDE_HULL && labels_.inside[t]; }

  /** s.star := the tetrahedra around vertex v, s.slot their places in it. */
  void gatherStar (std::uint32_t v, StarScratch& s) const
  {
    s.star.clear ();
    s.slot.clear ();
    s.v = v;
    const std::uint32_t first = tet_of_vertex_[v];
    if (first == NONE)
      return;
    s.star.push_back (first);
    s.slot.insert (first, 0);
    for (std::size_t k = 0; k < s.star.size (); ++k)
    {
      const std::uint32_t t = s.star[k];
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == v)
          continue; // the facet opposite v does not contain it
        const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
        if (u != OUTSIDE_HULL && s.slot.insert (u, static_cast<std::uint32_t> (s.star.size ())))
          s.star.push_back (u);
      }
    }
  }

  /** The connected parts, on each side, of the star's tetrahedra for which \a keep (index into
    * s.star) holds, joined across facets that contain s.v and every vertex \a through requires. */
  template <class Keep, class Through = bool (*) (std::uint32_t, int)>
  Parts split (StarScratch& s, const Keep& keep, const Through& through = [] (std::uint32_t, int) { return true; }) const
  {
    const std::size_t m = s.star.size ();
    std::vector<std::uint32_t>& parent = s.parent;
    parent.resize (m + 1);
    std::iota (parent.begin (), parent.end (), 0u);
    const auto find = [&] (std::uint32_t a) {
      while (parent[a] != a)
        a = parent[a] = parent[parent[a]];
      return a;
    };
    bool touches_hull = false;
    for (std::size_t k = 0; k < m; ++k)
    {
      if (!keep (static_cast<int> (k)))
        continue;
      const std::uint32_t t = s.star[k];
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == s.v || !through (t, i))
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
          const std::uint32_t j = s.slot.find (u);
          if (j != NONE && keep (static_cast<int> (j)))
            parent[find (static_cast<std::uint32_t> (k))] = find (j);
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
      const std::uint32_t r = find (static_cast<std::uint32_t> (k));
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
        parts.weight[p] += labels_.margin[s.star[k]];
        if (flipped_[s.star[k]])
          parts.movable[p] = 0;
      }
    }
    return parts;
  }

  /** The weakest movable part whose side has more than one part (moving the only part of a side
    * would take v off the surface); NONE if none. */
  static std::uint32_t weakest (const Parts& parts)
  {
    std::uint32_t best = NONE;
    for (std::uint32_t p = 0; p < parts.side.size (); ++p)
      if (parts.movable[p] && parts.count[parts.side[p]] > 1 &&
          (best == NONE || parts.weight[p] < parts.weight[best]))
        best = p;
    return best;
  }

  static std::vector<std::uint32_t> members (const StarScratch& s, const Parts& parts, std::uint32_t p)
  {
    std::vector<std::uint32_t> out;
    for (std::size_t k = 0; k < s.star.size (); ++k)
      if (parts.part[k] == p)
        out.push_back (s.star[k]);
    return out;
  }

  bool contains (std::uint32_t t, std::uint32_t vertex) const
  {
    const std::uint32_t* v = complex_.vertices (3, t);
    return v[0] == vertex || v[1] == vertex || v[2] == vertex || v[3] == vertex;
  }

  /** An edge (s.v, w) of the gathered star with more than two surface triangles: w, or NONE. */
  std::uint32_t pinchedEdge (StarScratch& s) const
  {
    s.edge_uses.clear ();
    for (std::uint32_t t : s.star)
      for (int i = 0; i < 4; ++i)
      {
        if (complex_.vertex (3, t, i) == s.v)
          continue;
        const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
        if (inside (t) == inside (u) || (u != OUTSIDE_HULL && inside (t) == 0))
          continue; // not a surface triangle, or counted from its inside tetrahedron
        for (int j = 0; j < 4; ++j)
        {
          const std::uint32_t w = complex_.vertex (3, t, j);
          if (j != i && w != s.v)
            s.edge_uses.push_back (w);
        }
      }
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

  /** The tetrahedra to move at v (empty: nothing to mend, or nothing allowed); \a pinched: the
    * surface touches itself at v (a pinched edge, or more than one fan). */
  std::vector<std::uint32_t> mendVertex (std::uint32_t v, StarScratch& s, bool& pinched) const
  {
    gatherStar (v, s);
    if (s.star.empty ())
      return {};
    // A pinched edge first: its ring's parts, joined only across facets that hold the edge.
    const std::uint32_t w = pinchedEdge (s);
    if (w != NONE)
    {
      const Parts ring = split (s, [&] (int k) { return contains (s.star[k], w); },
                                [&] (std::uint32_t t, int i) { return complex_.vertex (3, t, i) != w; });
      const std::uint32_t p = weakest (ring);
      if (p != NONE)
        return members (s, ring, p);
    }
    const Parts parts = split (s, [] (int) { return true; });
    pinched = w != NONE || parts.count[0] + parts.count[1] > 2;
    if (parts.count[0] + parts.count[1] > 2)
    {
      const std::uint32_t p = weakest (parts);
      if (p != NONE)
        return members (s, parts, p);
      return {};
    }
    if (parts.count[0] == 0 || parts.count[1] == 0)
    {
      // Buried or floating: move the weakest tetrahedron of the star that touches the other side.
      const bool buried = parts.count[0] == 0;
      std::uint32_t best = NONE;
      for (std::uint32_t t : s.star)
      {
        if (flipped_[t])
          continue;
        bool touches = false;
        for (int i = 0; i < 4 && !touches; ++i)
        {
          const std::uint32_t u = neighbours_[4 * std::size_t (t) + i];
          touches = buried ? !inside (u) : inside (u);
        }
        if (touches && (best == NONE || labels_.margin[t] < labels_.margin[best]))
          best = t;
      }
      if (best != NONE)
        return {best};
    }
    return {};
  }

  const SimplicialComplex& complex_;
  const FilledInParallel<std::uint32_t>& neighbours_;
  SolidLabels& labels_;
  std::vector<std::uint8_t> flipped_;
  std::vector<std::uint8_t> unmended_; // per vertex: left pinched when last looked at
  std::vector<std::uint32_t> tet_of_vertex_;
  StarScratch scratch_; // the sequential mending's
};

} // namespace

SolidRepair
repairSolid (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours, const Subcomplex& x,
             SolidLabels& labels)
{
  if (complex.dimension () != 3)
    return {};
  return Repairer (complex, neighbours, labels).run (x);
}

} // namespace pcl_wrap::detail
