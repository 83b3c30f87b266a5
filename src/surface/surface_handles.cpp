// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/surface_handles.h"

#include "surface/link_cycle.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"
#include "util/union_find.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

using Triangle = std::array<std::uint32_t, 3>;
using Edge = std::array<std::uint32_t, 2>;

/** The triangles around each vertex, each with its other two corners, so that a search over the
  * surface reads a vertex's neighbours from one run of memory: those of vertex v are
  * corner[begin[v] .. begin[v + 1]), by ascending triangle; found on all threads. */
struct TrianglesAround
{
  /** A triangle seen from one of its corners, v. */
  struct Corner
  {
    std::uint32_t tagged;                ///< the triangle, and in the top two bits which of its corners v is
    std::array<std::uint32_t, 2> others; ///< the triangle's other corners, in its order
    /** The opposite vertex of the last triangle around v with the edge from next() to v (the
      * other triangle on this one's edge from v), v where none has it. */
    std::uint32_t across;

    std::uint32_t triangle () const { return tagged & ~AT_MASK; }
    int at () const { return static_cast<int> (tagged >> AT_SHIFT); }
    /** The corner before v going round the triangle: the triangle has the edge from it to v. */
    std::uint32_t previous () const { return others[at () == 1 ? 0 : 1]; }
    /** The corner after v. */
    std::uint32_t next () const { return others[at () == 1 ? 1 : 0]; }
    /** The triangle, its corners in its order, v among them. */
    Triangle corners (std::uint32_t v) const
    {
      const int i = at ();
      return i == 0   ? Triangle{v, others[0], others[1]}
             : i == 1 ? Triangle{others[0], v, others[1]}
                      : Triangle{others[0], others[1], v};
    }
  };
  static constexpr int AT_SHIFT = 30;
  static constexpr std::uint32_t AT_MASK = std::uint32_t (3) << AT_SHIFT;

  std::vector<std::size_t> begin;
  FilledInParallel<Corner> corner;

  TrianglesAround (const std::vector<Triangle>& triangles, std::uint32_t n)
    : corner (bucketInParallel<Corner> (
          checkedCount (triangles.size ()), n,
          [&] (std::size_t k, auto put) {
            const Triangle& t = triangles[k];
            const auto id = static_cast<std::uint32_t> (k);
            put (t[0], Corner{id, {t[1], t[2]}, 0});
            put (t[1], Corner{id | (1u << AT_SHIFT), {t[0], t[2]}, 0});
            put (t[2], Corner{id | (2u << AT_SHIFT), {t[0], t[1]}, 0});
          },
          begin,
          [] (std::size_t v, auto first, auto last) {
            for (auto c = first; c != last; ++c)
              c->across = acrossEdge (first, last, static_cast<std::uint32_t> (v), c->next ());
          }))
  {}

  /** The opposite vertex of the last triangle around \a a with the edge from \a b to \a a; \a a
    * where none has it. */
  std::uint32_t oppositeOfEdge (std::uint32_t a, std::uint32_t b) const
  {
    return acrossEdge (corner.begin () + begin[a], corner.begin () + begin[a + 1], a, b);
  }

private:
  /** Of the corners [first, last) around \a a, the next() of the last whose previous() is \a b;
    * \a a where none is. */
  template <class It>
  static std::uint32_t acrossEdge (It first, It last, std::uint32_t a, std::uint32_t b)
  {
    std::uint32_t found = a;
    for (; first != last; ++first)
      if (first->previous () == b)
        found = first->next ();
    return found;
  }

  static std::size_t checkedCount (std::size_t triangles)
  {
    if (triangles > ~AT_MASK)
      throw std::length_error ("pcl_wrap: a surface of 2^30 triangles or more");
    return triangles;
  }
};

/** atan2 (y, x) for y >= 0, within 2e-5: a polynomial for the arc tangent on [0, 1]. */
double
angleOf (double y, double x)
{
  const double ax = std::fabs (x), high = std::max (ax, y);
  if (high == 0.0)
    return 0.0;
  const double z = std::min (ax, y) / high, z2 = z * z;
  double a = z * (0.99997726 +
                  z2 * (-0.33262347 + z2 * (0.19354346 + z2 * (-0.11643287 + z2 * (0.05265332 + z2 * -0.01172120)))));
  if (y > ax)
    a = M_PI / 2 - a;
  return x < 0 ? M_PI - a : a;
}

/** The vertices flagged in \a look at which the angles of the triangles around them add up to
  * more than 2 pi + SADDLE_EXCESS, ascending. The angles are added up in fixed point, on all
  * threads: integer sums do not depend on the order. */
std::vector<std::uint32_t>
sharpSaddles (const std::vector<Triangle>& triangles, const std::vector<std::array<double, 3>>& positions,
              const std::vector<std::uint8_t>& look)
{
  constexpr double UNIT = 1099511627776.0; // 2^40 units to a radian
  constexpr auto HALF_TURN = static_cast<std::int64_t> (M_PI * UNIT);
  // Coordinates within these sizes are used as they are: the squares of the cross product's
  // components cannot overflow, and the scaling would change no bit of a result in normal range.
  constexpr double UNSCALED_BELOW = 0x1p200, UNSCALED_ABOVE = 0x1p-200;
  std::vector<std::int64_t> sum (look.size (), 0);
  parallelForEach (triangles.size (), [&] (std::size_t k) {
    const Triangle& t = triangles[k];
    if (!look[t[0]]) // nor its other vertices, of the same part
      return;
    // Huge coordinates would overflow in the cross product's squares, tiny ones underflow: the
    // corners are then scaled by a power of two (exactly) to coordinates below 1 in size.
    double largest = 0.0;
    for (std::uint32_t v : t)
      for (double c : positions[v])
        largest = std::max (largest, std::fabs (c));
    std::array<std::array<double, 3>, 3> corner{positions[t[0]], positions[t[1]], positions[t[2]]};
    if (!(largest < UNSCALED_BELOW && largest > UNSCALED_ABOVE))
    {
      const int exponent = largest > 0.0 ? std::ilogb (largest) + 1 : 0;
      for (auto& p : corner)
        for (double& c : p)
          c = std::ldexp (c, -exponent);
    }
    std::int64_t third = HALF_TURN; // the angles of a triangle add up to pi
    for (int i = 0; i < 2; ++i)
    {
      const std::array<double, 3>&p = corner[i], &q = corner[(i + 1) % 3], &r = corner[(i + 2) % 3];
      const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
      const double c[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const auto angle = static_cast<std::int64_t> (UNIT * angleOf (std::sqrt (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                                                                    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]));
      relaxedFetchAdd (&sum[t[i]], angle);
      third -= angle;
    }
    relaxedFetchAdd (&sum[t[2]], third);
  });
  const auto above = static_cast<std::int64_t> ((2.0 * M_PI + SADDLE_EXCESS) * UNIT);
  return indicesWhere (sum.size (), [&] (std::size_t v) { return sum[v] > above; });
}

/** One thread's marks and lists, reused from vertex to vertex. */
struct PatchScratch
{
  std::vector<std::uint32_t> in_patch, seen; // per vertex: the stamp of the last patch (search) to reach it
  std::uint32_t stamp = 0, search = 0;
  std::vector<std::uint32_t> vertices, front, next;
  std::vector<std::int16_t> level; // per vertex of a tunnel's patch: SmallHandlePatches::level
  std::vector<Edge> edges;
  std::vector<std::uint32_t> edge_triangle;                     // per boundary edge: its triangle
  std::vector<std::pair<std::uint32_t, std::uint32_t>> loop_of; // boundary vertex, its loop
  UnionFind loops;
  // Where the patch touches itself: per boundary vertex, its first fan's node (fan_node), and
  // per pinched one, its triangles in the patch with the fan of each (fans).
  std::vector<std::uint32_t> fan_node;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fans; // triangle, fan
  std::vector<std::uint32_t> fans_begin;                     // per boundary vertex: into fans
  UnionFind fan_sets, fan_loops;
};

/** What a patch says of the surface near its centre. */
enum class HandleKind
{
  none,   ///< no small handle
  handle, ///< a small handle, to be cut or filled
  tunnel, ///< a thin tube between two wider parts of the surface: a tunnel through a wall, or a web
  /** a thin tube whose two ends the surface does not join near, past at most one of which it
    * opens out: a web between two small objects, a finger, a tail */
  neck
};

/** The patches of a closed surface around its vertices, and what their topology says. */
class HandleFinder
{
public:
  HandleFinder (const std::vector<Triangle>& triangles, const TrianglesAround& around, std::uint32_t n, int rings)
    : triangles_ (triangles), around_ (around), n_ (n), rings_ (rings)
  {}

  /** Does the patch of rings_ rings around \a v hold a handle or go round a handle's tube?
    * A tube whose ends the surface joins only far away is a tunnel when the surface opens out
    * past both of them: a hole through a wall that the points do not resolve, or a web across a
    * gap between two walls (a solid tube, which may also be a thin wire the points do show).
    * With \a necks, a tube with two boundary loops past which the surface does not open out
    * both ways is a neck. */
  HandleKind onSmallHandle (std::uint32_t v, PatchScratch& s, bool necks) const
  {
    if (s.in_patch.empty ())
    {
      s.in_patch.assign (n_, 0);
      s.seen.assign (n_, 0);
    }
    const std::uint32_t stamp = ++s.stamp;
    // The rings: every vertex of a triangle around a vertex of the ring before.
    s.vertices.assign (1, v);
    s.in_patch[v] = stamp;
    s.front.assign (1, v);
    std::size_t inner = 0; // the vertices of the rings before the last, whose neighbours are all in it
    for (int ring = 0; ring < rings_; ++ring)
    {
      inner = s.vertices.size ();
      nextRing (s.front, s.next, [&] (std::uint32_t, std::uint32_t w) {
        if (s.in_patch[w] == stamp)
          return false;
        s.in_patch[w] = stamp;
        s.vertices.push_back (w);
        return true;
      });
    }
    // The patch's triangles (those with three vertices in it) and its boundary edges (on one of
    // them): V - E + F with E = (3 F + boundary) / 2. Each is counted at its corners, from what
    // lies around the corner's vertex alone: a triangle's edge at the corner it starts from.
    long corners = 0, boundary = 0;
    for (std::size_t i = 0; i < s.vertices.size (); ++i)
    {
      const std::uint32_t u = s.vertices[i];
      const std::size_t first = around_.begin[u], last = around_.begin[u + 1];
      if (i < inner)
      {
        // Every triangle around it is in the patch, and an edge from it is on the boundary only
        // where no triangle is across.
        corners += static_cast<long> (last - first);
        for (std::size_t k = first; k < last; ++k)
          boundary += around_.corner[k].across == u;
        continue;
      }
      for (std::size_t k = first; k < last; ++k)
      {
        const TrianglesAround::Corner& c = around_.corner[k];
        if (s.in_patch[c.others[0]] != stamp || s.in_patch[c.others[1]] != stamp)
          continue;
        ++corners;
        boundary += c.across == u || s.in_patch[c.across] != stamp;
      }
    }
    const long faces = corners / 3, chi = long (s.vertices.size ()) - (3 * faces + boundary) / 2 + faces;
    if (chi >= 1)
      return HandleKind::none; // a disc (or a whole small sphere)
    // The boundary edges, triangle by triangle.
    s.edges.clear ();
    s.edge_triangle.clear ();
    for (std::uint32_t u : s.vertices)
      for (std::size_t k = around_.begin[u]; k < around_.begin[u + 1]; ++k)
      {
        const TrianglesAround::Corner& c = around_.corner[k];
        const Triangle t = c.corners (u);
        if (u != std::min ({t[0], t[1], t[2]}) || s.in_patch[t[0]] != stamp || s.in_patch[t[1]] != stamp ||
            s.in_patch[t[2]] != stamp)
          continue;
        for (int i = 0; i < 3; ++i)
        {
          const std::uint32_t d = around_.oppositeOfEdge (t[i], t[(i + 1) % 3]);
          if (d == t[i] || s.in_patch[d] != stamp)
          {
            s.edges.push_back ({t[i], t[(i + 1) % 3]});
            s.edge_triangle.push_back (c.triangle ());
          }
        }
      }
    // Its boundary loops.
    s.loop_of.clear ();
    for (const Edge& e : s.edges)
      for (std::uint32_t w : e)
        s.loop_of.push_back ({w, 0});
    std::sort (s.loop_of.begin (), s.loop_of.end ());
    s.loop_of.erase (std::unique (s.loop_of.begin (), s.loop_of.end ()), s.loop_of.end ());
    const auto local = [&] (std::uint32_t w) {
      return static_cast<std::uint32_t> (
          std::lower_bound (s.loop_of.begin (), s.loop_of.end (), std::make_pair (w, 0u)) - s.loop_of.begin ());
    };
    s.loops.reset (s.loop_of.size ());
    for (const Edge& e : s.edges)
    {
      const std::uint32_t p = s.loops.find (local (e[0])), q = s.loops.find (local (e[1]));
      if (p != q)
        s.loops.attach (p, q);
    }
    long loops = 0;
    std::array<std::uint32_t, 2> ends{}; // the first two loops
    for (std::uint32_t i = 0; i < s.loop_of.size (); ++i)
    {
      s.loop_of[i].second = s.loops.find (i);
      if (s.loop_of[i].second == i && loops < 2)
        ends[loops] = i;
      loops += s.loop_of[i].second == i;
    }
    if (ownGenus (s, stamp, chi, loops, local))
      return HandleKind::handle;
    if (loops < 2)
      return HandleKind::none;
    if (loopsJoinNear (s, stamp, local))
      return HandleKind::handle;
    std::array<std::uint32_t, 2> open{};
    int opening = 0;
    for (std::uint32_t i = 0; i < s.loop_of.size () && opening < 2; ++i)
      if (s.loop_of[i].second == i && opensOut (s, stamp, i))
        open[opening++] = i;
    if (opening == 2)
    {
      measureFromEnds (s, stamp, open);
      return HandleKind::tunnel;
    }
    if (!necks || loops != 2)
      return HandleKind::none;
    measureFromEnds (s, stamp, ends);
    return HandleKind::neck;
  }

  /** Has the patch (Euler characteristic \a chi, \a loops boundary loops when a vertex on
    * several is one) a genus of its own? A boundary vertex where the patch touches itself, its
    * triangles there in several fans (a pinch: more than two boundary edges), counts once per fan
    * (each fan a vertex of its own on the loops), as a surface's pinch does: a band round a
    * thin tube whose two rims meet at a vertex is an annulus, not a patch with a handle. */
  template <class Local>
  bool ownGenus (PatchScratch& s, std::uint32_t stamp, long chi, long loops, const Local& local) const
  {
    const std::size_t n = s.loop_of.size ();
    s.fan_node.assign (n + 1, 0);
    for (const Edge& e : s.edges)
      for (std::uint32_t w : e)
        ++s.fan_node[local (w)]; // boundary edges at each vertex, for now
    bool pinched = false;
    for (std::size_t i = 0; i < n; ++i)
      pinched = pinched || s.fan_node[i] > 2;
    if (!pinched)
      return 2 - chi - loops >= 2;
    // The fans at each pinched vertex: its triangles in the patch, joined where two share an edge.
    s.fans.clear ();
    s.fans_begin.assign (n + 1, 0);
    std::uint32_t nodes = 0;
    for (std::size_t i = 0; i < n; ++i)
    {
      const std::uint32_t w = s.loop_of[i].first, first = static_cast<std::uint32_t> (s.fans.size ());
      s.fans_begin[i] = first;
      const bool pinch = s.fan_node[i] > 2;
      s.fan_node[i] = nodes;
      if (!pinch)
      {
        ++nodes;
        continue;
      }
      for (std::size_t k = around_.begin[w]; k < around_.begin[w + 1]; ++k)
      {
        const TrianglesAround::Corner& c = around_.corner[k];
        if (s.in_patch[c.others[0]] == stamp && s.in_patch[c.others[1]] == stamp)
          s.fans.push_back ({c.triangle (), 0});
      }
      // The fans: sets of triangles joined pairwise (a few), each set's root its least index.
      const auto here = static_cast<std::uint32_t> (s.fans.size () - first);
      s.fan_sets.reset (here);
      for (std::uint32_t a = 0; a < here; ++a)
        for (std::uint32_t b = a + 1; b < here; ++b)
          if (shareEdgeAt (s.fans[first + a].first, s.fans[first + b].first, w))
          {
            const std::uint32_t p = s.fan_sets.find (a), q = s.fan_sets.find (b);
            if (p != q)
              s.fan_sets.attach (std::max (p, q), std::min (p, q));
          }
      // Fans numbered from 0 on, in the order of their least triangles.
      std::uint32_t count = 0;
      for (std::uint32_t a = 0; a < here; ++a)
      {
        const std::uint32_t root = s.fan_sets.find (a);
        s.fans[first + a].second = root == a ? count++ : s.fans[first + root].second;
      }
      nodes += count;
      chi += count - 1; // the pinched vertex, split into one per fan
    }
    s.fans_begin[n] = static_cast<std::uint32_t> (s.fans.size ());
    // The loops, with the pinched vertices split.
    const auto node = [&] (std::uint32_t w, std::uint32_t triangle) {
      const std::uint32_t i = local (w);
      for (std::uint32_t a = s.fans_begin[i]; a < s.fans_begin[i + 1]; ++a)
        if (s.fans[a].first == triangle)
          return s.fan_node[i] + s.fans[a].second;
      return s.fan_node[i];
    };
    s.fan_loops.reset (nodes);
    for (std::size_t e = 0; e < s.edges.size (); ++e)
    {
      const std::uint32_t p = s.fan_loops.find (node (s.edges[e][0], s.edge_triangle[e])),
                          q = s.fan_loops.find (node (s.edges[e][1], s.edge_triangle[e]));
      if (p != q)
        s.fan_loops.attach (p, q);
    }
    long split_loops = 0;
    for (std::uint32_t k = 0; k < nodes; ++k)
      split_loops += s.fan_loops.find (k) == k;
    return 2 - chi - split_loops >= 2;
  }

  /** Do triangles \a a and \a b, both with vertex \a w, share an edge at \a w? */
  bool shareEdgeAt (std::uint32_t a, std::uint32_t b, std::uint32_t w) const
  {
    for (std::uint32_t x : triangles_[a])
      if (x != w && (triangles_[b][0] == x || triangles_[b][1] == x || triangles_[b][2] == x))
        return true;
    return false;
  }

  /** Clears the flags in \a look of the vertices more than \a rings rings from all of \a seeds. */
  void keepNear (const std::vector<std::uint32_t>& seeds, int rings, std::vector<std::uint8_t>& look) const
  {
    std::vector<std::uint8_t> near (n_, 0);
    std::vector<std::uint32_t> front, next;
    for (std::uint32_t v : seeds)
      if (!near[v])
      {
        near[v] = 1;
        front.push_back (v);
      }
    for (int ring = 0; ring < rings && !front.empty (); ++ring)
      nextRing (front, next, [&] (std::uint32_t, std::uint32_t w) {
        if (near[w])
          return false;
        near[w] = 1;
        return true;
      });
    for (std::uint32_t v = 0; v < n_; ++v)
      look[v] = look[v] && near[v];
  }

  /** Keeps, of the vertices flagged in \a look, those of a maximal independent set, taken in
    * the order of the ids: every flagged vertex is kept or next to one that is. */
  void keepCentres (std::vector<std::uint8_t>& look) const
  {
    for (std::uint32_t v = 0; v < n_; ++v)
      if (look[v] == 1)
        forNeighbours (v, [&] (std::uint32_t w) {
          if (w > v && look[w] == 1)
            look[w] = 2; // next to a centre
        });
    for (auto& flag : look)
      flag = flag == 1;
  }

private:
  template <class F>
  void forNeighbours (std::uint32_t u, const F& f) const
  {
    for (std::size_t k = around_.begin[u]; k < around_.begin[u + 1]; ++k)
      for (std::uint32_t w : around_.corner[k].others)
        f (w);
  }

  /** One ring of a search over the surface: the next front is the neighbours w of the front's
    * vertices u that \a claim (u, w) takes (marking them as reached); it is then the front. */
  template <class Claim>
  void nextRing (std::vector<std::uint32_t>& front, std::vector<std::uint32_t>& next, const Claim& claim) const
  {
    next.clear ();
    for (std::uint32_t u : front)
      forNeighbours (u, [&] (std::uint32_t w) {
        if (claim (u, w))
          next.push_back (w);
      });
    front.swap (next);
  }

  /** Starts a new search at the vertices of the patch's boundary loop \a loop: they make the
    * front, marked seen by the search. Returns the search's stamp. */
  static std::uint32_t startAtLoop (PatchScratch& s, std::uint32_t loop)
  {
    const std::uint32_t search = ++s.search;
    s.front.clear ();
    for (const auto& [w, l] : s.loop_of)
      if (l == loop)
      {
        s.front.push_back (w);
        s.seen[w] = search;
      }
    return search;
  }

  /** Does a path off the patch, within 2 rings_ rings, join its first boundary loop to
    * another? */
  template <class Local>
  bool loopsJoinNear (PatchScratch& s, std::uint32_t stamp, const Local& local) const
  {
    const std::uint32_t first = s.loop_of.front ().second, search = startAtLoop (s, first);
    bool joined = false;
    for (int ring = 0; ring < 2 * rings_ && !joined && !s.front.empty (); ++ring)
      nextRing (s.front, s.next, [&] (std::uint32_t u, std::uint32_t w) {
        if (s.seen[w] == search)
          return false;
        if (s.in_patch[w] != stamp)
        {
          s.seen[w] = search;
          return true;
        }
        if (s.in_patch[u] != stamp) // from off the patch onto its boundary
        {
          const std::uint32_t i = local (w);
          joined = joined || (i < s.loop_of.size () && s.loop_of[i].first == w && s.loop_of[i].second != first);
        }
        return false;
      });
    return joined;
  }

  /** Sets, for each vertex of the patch, its rings within the patch from the boundary loop
    * ends[0] less its rings from ends[1] (s.level): the first search writes its rings, the
    * second takes its own away. */
  void measureFromEnds (PatchScratch& s, std::uint32_t stamp, const std::array<std::uint32_t, 2>& ends) const
  {
    if (s.level.empty ())
      s.level.assign (n_, 0);
    for (int e = 0; e < 2; ++e)
    {
      const std::uint32_t search = startAtLoop (s, ends[e]);
      for (std::int16_t ring = 0; !s.front.empty (); ++ring)
      {
        for (std::uint32_t u : s.front)
          s.level[u] = e == 0 ? ring : std::int16_t (s.level[u] - ring);
        nextRing (s.front, s.next, [&] (std::uint32_t, std::uint32_t w) {
          if (s.in_patch[w] != stamp || s.seen[w] == search)
            return false;
          s.seen[w] = search;
          return true;
        });
      }
    }
  }

  /** Does the surface open out past the patch's boundary loop \a loop: does a search off the
    * patch from it reach, 2 rings_ rings on, more than twice as many vertices as the loop
    * has? Along a tube the front stays as long as the loop; on a wall it grows with every ring. */
  bool opensOut (PatchScratch& s, std::uint32_t stamp, std::uint32_t loop) const
  {
    const std::uint32_t search = startAtLoop (s, loop);
    const std::size_t length = s.front.size ();
    for (int ring = 0; ring < 2 * rings_ && !s.front.empty (); ++ring)
      nextRing (s.front, s.next, [&] (std::uint32_t, std::uint32_t w) {
        if (s.seen[w] == search || s.in_patch[w] == stamp)
          return false;
        s.seen[w] = search;
        return true;
      });
    return s.front.size () > 2 * length;
  }

  const std::vector<Triangle>& triangles_;
  const TrianglesAround& around_;
  const std::uint32_t n_;
  const int rings_; ///< how many rings of triangles around a vertex make its patch
};

/** Calls \a f (t, first) for each triangle t around \a v, with first one triangle of t's fan there
  * (a connected part of v's link), the same for the whole fan; returns how many fans there are:
  * one where the surface is a 2-manifold, more where it touches itself at v (a pinch). */
template <class F>
std::uint32_t
forEachFanMember (const TrianglesAround& around, std::uint32_t v, const F& f)
{
  const std::size_t first = around.begin[v], k = around.begin[v + 1] - first;
  const auto corner = [&] (std::size_t e) -> const TrianglesAround::Corner& { return around.corner[first + e]; };
  const auto edge = [&] (std::size_t e) { return std::make_pair (corner (e).next (), corner (e).previous ()); };
  if (k == 0)
    return 0;
  if (isOneShortCycle (k, edge))
  {
    for (std::size_t e = 0; e < k; ++e)
      f (corner (e).triangle (), corner (0).triangle ());
    return 1;
  }
  std::vector<std::uint32_t> fan_of (k);
  const LinkShape shape = linkShape (k, edge, fan_of.data ());
  for (std::size_t e = 0; e < k; ++e)
    f (corner (e).triangle (), corner (fan_of[e]).triangle ());
  return shape.parts;
}

/** The closed surfaces a surface is made of: its triangles joined where they share an edge, so
  * that where the surface touches itself at a vertex (a pinch the mending left, split after the
  * repair) the surfaces meeting there are parts of their own. Joined there, a sphere (an unsampled
  * void touching the outside at a vertex) would add 2 to a torus's V - F / 2 and hide its
  * handle. Found on all threads. */
struct SurfaceParts
{
  static constexpr std::uint32_t NONE = ~std::uint32_t (0);

  std::vector<std::uint32_t> of_triangle; ///< per triangle, its part
  std::vector<long> faces;                ///< per part
  std::vector<long> vertices;             ///< per part, each vertex once per fan of its triangles there
  std::vector<std::uint8_t> pinched;      ///< per part: it touches itself or another part at a vertex
  std::vector<std::uint32_t> of_vertex;   ///< per vertex, the part of its first triangle (NONE: none)
  std::vector<std::uint8_t> pinch;        ///< per vertex: its triangles make more than one fan

  SurfaceParts (const std::vector<Triangle>& triangles, const TrianglesAround& around, std::uint32_t n)
    : of_vertex (n, NONE), pinch (n, 0)
  {
    const std::size_t f = triangles.size ();
    UnionFind sets;
    sets.resetInParallel (f);
    // Triangles that share an edge at a vertex are in one fan there: each joined to the fan's
    // first.
    parallelForEach (n, [&] (std::size_t v) {
      const std::uint32_t fans =
          forEachFanMember (around, static_cast<std::uint32_t> (v), [&] (std::uint32_t t, std::uint32_t first) {
            if (t != first)
              sets.uniteConcurrently (first, t);
          });
      pinch[v] = fans > 1;
    });
    // Each root the lowest triangle of its part: numbered in ascending order.
    of_triangle.resize (f);
    std::uint32_t parts = 0;
    for (std::size_t k = 0; k < f; ++k)
      of_triangle[k] = sets.isRoot (static_cast<std::uint32_t> (k)) ? parts++ : of_triangle[sets.find (k)];
    faces.assign (parts, 0);
    vertices.assign (parts, 0);
    pinched.assign (parts, 0);
    for (std::uint32_t p : of_triangle)
      ++faces[p];
    parallelForEach (n, [&] (std::size_t v) {
      if (around.begin[v] < around.begin[v + 1])
        of_vertex[v] = of_triangle[around.corner[around.begin[v]].triangle ()];
    });
    for (std::uint32_t v = 0; v < n; ++v)
      forEachPartAt (around, v, [&] (std::uint32_t p) {
        ++vertices[p];
        pinched[p] = pinched[p] || pinch[v];
      });
  }

  /** Is part \a p a closed surface of genus above 0 (V - F / 2 = 2 - 2 g)? */
  bool hasGenus (std::uint32_t p) const { return faces[p] % 2 == 0 && vertices[p] - faces[p] / 2 < 2; }

  /** Calls \a f with the part of each fan of triangles around \a v. */
  template <class F>
  void forEachPartAt (const TrianglesAround& around, std::uint32_t v, const F& f) const
  {
    if (!pinch[v])
    {
      if (of_vertex[v] != NONE)
        f (of_vertex[v]);
      return;
    }
    forEachFanMember (around, v, [&] (std::uint32_t t, std::uint32_t first) {
      if (t == first)
        f (of_triangle[t]);
    });
  }
};

/** smallHandlePatches(), or with \a wide wideTunnelPatches(). */
SmallHandlePatches
handlePatches (const std::vector<Triangle>& triangles, std::uint32_t num_vertices,
               const std::vector<std::uint32_t>* near, const std::vector<std::array<double, 3>>* positions, bool wide)
{
  const int rings = wide ? WIDE_TUNNEL_RINGS : HANDLE_RINGS;
  const TrianglesAround around (triangles, num_vertices);
  const SurfaceParts parts (triangles, around, num_vertices);
  // Per vertex: whether one of its parts has a genus, whether one is a closed surface of genus 0
  // (where the sharp saddles are looked for; not a part with a pinch, whose angles there add up
  // over several fans), and the part of its first triangle.
  const bool saddles_looked_for = positions && !wide;
  std::vector<std::uint8_t> look (num_vertices, 0), of_genus_zero;
  if (saddles_looked_for)
    of_genus_zero.assign (num_vertices, 0);
  parallelForEach (num_vertices, [&] (std::size_t v) {
    parts.forEachPartAt (around, static_cast<std::uint32_t> (v), [&] (std::uint32_t p) {
      if (parts.hasGenus (p))
        look[v] = 1;
      else if (saddles_looked_for && parts.faces[p] % 2 == 0 && !parts.pinched[p])
        of_genus_zero[v] = 1;
    });
  });
  bool on_handles = std::find (look.begin (), look.end (), 1) != look.end ();
  const bool any_of_genus_zero = std::find (of_genus_zero.begin (), of_genus_zero.end (), 1) != of_genus_zero.end ();
  const std::vector<std::uint32_t>& part = parts.of_vertex;
  SmallHandlePatches out;
  out.has_genus = on_handles && !wide;
  if (!on_handles && !any_of_genus_zero)
    return out;
  std::vector<std::uint32_t> saddles;
  if (any_of_genus_zero)
    saddles = sharpSaddles (triangles, *positions, of_genus_zero);
  std::vector<std::uint8_t> of_tunnel_ends;
  if (wide && on_handles)
  {
    // The sharp saddles of the parts with a genus, where a tunnel's tube ends, as a web's does;
    // but only on a part where they are few. Where noise makes them common, they mark no tube.
    const std::vector<std::uint32_t> ends = sharpSaddles (triangles, *positions, look);
    std::vector<long> saddles_of (parts.faces.size (), 0);
    for (std::uint32_t v : ends)
      ++saddles_of[part[v]];
    on_handles = false;
    for (std::uint32_t v = 0; v < num_vertices; ++v)
    {
      look[v] = look[v] && saddles_of[part[v]] * WIDE_TUNNEL_SADDLE_SHARE <= parts.vertices[part[v]];
      on_handles = on_handles || look[v];
    }
    of_tunnel_ends.assign (num_vertices, 0);
    for (std::uint32_t v : ends)
      of_tunnel_ends[v] = 1;
  }
  if (!on_handles && saddles.empty ())
    return out;
  const HandleFinder finder (triangles, around, num_vertices, rings);
  if (wide)
    for (std::uint32_t v = 0; v < num_vertices; ++v)
      look[v] = look[v] && of_tunnel_ends[v];
  else if (!saddles.empty ())
  {
    // The saddles and their neighbours: the patch around one next to a tube's end goes round it.
    finder.keepNear (saddles, 1, of_genus_zero);
    for (std::uint32_t v = 0; v < num_vertices; ++v)
      look[v] = look[v] || of_genus_zero[v];
  }
  if (near)
    finder.keepNear (*near, 2 * rings, look);
  finder.keepCentres (look);
  struct Found
  {
    std::uint32_t centre;
    bool tunnel, neck;
    std::vector<std::pair<std::uint32_t, std::int8_t>> patch; // sorted (vertex, level)
    bool operator<(const Found& o) const { return centre < o.centre; }
  };
  tbb::enumerable_thread_specific<std::pair<PatchScratch, std::vector<Found>>> found;
  parallelForEach (
      num_vertices,
      [&] (std::size_t v) {
        if (!look[v])
          return;
        auto& [scratch, list] = found.local ();
        // A neck only on a part of genus 0, where it may be the last tie of two objects.
        const bool necks = !of_genus_zero.empty () && of_genus_zero[v];
        const HandleKind kind = finder.onSmallHandle (static_cast<std::uint32_t> (v), scratch, necks);
        if (kind == HandleKind::none || (wide && kind != HandleKind::tunnel))
          return;
        Found& f = list.emplace_back (
            Found{static_cast<std::uint32_t> (v), kind == HandleKind::tunnel, kind == HandleKind::neck, {}});
        for (std::uint32_t w : scratch.vertices)
          f.patch.emplace_back (w, f.tunnel || f.neck ? std::int8_t (scratch.level[w]) : 0);
        std::sort (f.patch.begin (), f.patch.end ());
      },
      256);
  std::vector<Found> all;
  for (auto& [scratch, list] : found)
    std::move (list.begin (), list.end (), std::back_inserter (all));
  std::sort (all.begin (), all.end ());
  out.begin.push_back (0);
  for (const Found& f : all)
  {
    out.centres.push_back (f.centre);
    out.tunnel.push_back (f.tunnel);
    out.neck.push_back (f.neck);
    for (const auto& [w, level] : f.patch)
    {
      out.vertices.push_back (w);
      out.level.push_back (level);
    }
    out.begin.push_back (static_cast<std::uint32_t> (out.vertices.size ()));
  }
  return out;
}

} // namespace

SmallHandlePatches
smallHandlePatches (const std::vector<Triangle>& triangles, std::uint32_t num_vertices,
                    const std::vector<std::uint32_t>* near, const std::vector<std::array<double, 3>>* positions)
{
  return handlePatches (triangles, num_vertices, near, positions, false);
}

SmallHandlePatches
wideTunnelPatches (const std::vector<Triangle>& triangles, std::uint32_t num_vertices,
                   const std::vector<std::array<double, 3>>& positions)
{
  return handlePatches (triangles, num_vertices, nullptr, &positions, true);
}

} // namespace pcl_wrap::detail
