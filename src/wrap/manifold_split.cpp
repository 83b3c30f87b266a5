// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/manifold_split.h"

#include "util/union_find.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

struct Face
{
  std::array<std::uint32_t, 3> v; // oriented: its normal points into the outside
  SimplexId triangle;
  bool reversed; // the second side of a sheet triangle
};

bool
traverses (const Face& f, std::uint32_t a, std::uint32_t b)
{
  for (int i = 0; i < 3; ++i)
    if (f.v[i] == a && f.v[(i + 1) % 3] == b)
      return true;
  return false;
}

int
cornerOf (const Face& f, std::uint32_t vertex)
{
  return f.v[0] == vertex ? 0 : f.v[1] == vertex ? 1 : 2;
}

/** The sign of the permutation p of (0, 1, 2, 3). */
bool
isEven (std::array<int, 4> p)
{
  bool even = true;
  for (int i = 0; i < 4; ++i)
    while (p[i] != i)
    {
      std::swap (p[i], p[p[i]]);
      even = !even;
    }
  return even;
}

/** One step around edge (a, b): the tetrahedron from triangle (a, b, c) to (a, b, d), with
  * (a, b, c, d) positively oriented, and the ids of both triangles. */
struct Step
{
  std::uint32_t c, d;
  SimplexId tet, triangle_c, triangle_d;
};

/** The two vertices of the edge with key \a key (edgeKey()), lower first. */
std::array<std::uint32_t, 2>
edgeEnds (std::uint64_t key)
{
  return {std::uint32_t (key >> 32), std::uint32_t (key)};
}

/** Every non-crossing perfect matching of 2k points on a circle (k >= 1), at most \a cap of them:
  * each pairs points an odd distance apart. */
void
nonCrossingMatchings (std::vector<int>& open, std::vector<std::pair<int, int>>& pairs,
                      std::vector<std::vector<std::pair<int, int>>>& out, std::size_t cap)
{
  if (out.size () >= cap)
    return;
  if (open.empty ())
  {
    out.push_back (pairs);
    return;
  }
  // Pair the first open point with one an odd number of places on; what lies between is
  // matched among itself, what lies beyond among itself.
  const int first = open[0];
  for (std::size_t j = 1; j < open.size (); j += 2)
  {
    std::vector<int> rest (open.begin () + 1, open.begin () + j);
    rest.insert (rest.end (), open.begin () + j + 1, open.end ());
    pairs.emplace_back (first, open[j]);
    nonCrossingMatchings (rest, pairs, out, cap);
    pairs.pop_back ();
  }
}

/** facesAroundEdge()'s lists, reused from edge to edge. */
struct AroundEdge
{
  std::vector<Step> steps;
  std::vector<SimplexId> triangle;    // around the edge, in rotation order
  std::vector<std::uint8_t> gap_in_x; // the tetrahedron after each triangle (omega: not in X)
  std::vector<std::uint32_t> around;  // the faces, in rotation order
};

/** The faces on the pinch edge (a, b) (a < b) in the rotation order of the tetrahedra of Del S
  * around it (docs/design.md §8), into \a scratch.around: it starts with a face looking back, so
  * that pairs (0, 1), (2, 3)... are across X and pairs (1, 2), ..., (2k - 1, 0) across the
  * outside. */
void
facesAroundEdge (const SimplicialComplex& complex, const Subcomplex& x, std::uint32_t a, std::uint32_t b,
                 const std::vector<SimplexId>& tets, const std::vector<std::uint32_t>& faces_here,
                 const std::vector<Face>& faces, AroundEdge& scratch)
{
  std::vector<Step>& steps = scratch.steps;
  steps.clear ();
  for (SimplexId t : tets)
  {
    const std::uint32_t* v = complex.vertices (3, t);
    std::array<int, 4> local{};
    int other = 2;
    for (int i = 0; i < 4; ++i)
      local[v[i] == a ? 0 : v[i] == b ? 1 : other++] = i;
    if (!isEven (local))
      std::swap (local[2], local[3]);
    const unsigned ab = (1u << local[0]) | (1u << local[1]);
    steps.push_back ({v[local[2]], v[local[3]], t, complex.face (3, t, ab | (1u << local[2])).id,
                      complex.face (3, t, ab | (1u << local[3])).id});
  }
  // Order the steps into a cycle, or a path from the hull round to the hull (omega closes it).
  std::size_t start = 0;
  for (std::size_t i = 0; i < steps.size (); ++i)
    if (std::none_of (steps.begin (), steps.end (), [&] (const Step& s) { return s.d == steps[i].c; }))
      start = i;
  std::vector<SimplexId>& triangle = scratch.triangle;
  std::vector<std::uint8_t>& gap_in_x = scratch.gap_in_x;
  triangle.clear ();
  gap_in_x.clear ();
  for (std::size_t i = start, n = 0; n < steps.size (); ++n)
  {
    triangle.push_back (steps[i].triangle_c);
    gap_in_x.push_back (x.contains ({3, steps[i].tet}));
    const auto next = std::find_if (steps.begin (), steps.end (), [&] (const Step& s) { return s.c == steps[i].d; });
    if (next == steps.end ())
    {
      triangle.push_back (steps[i].triangle_d);
      gap_in_x.push_back (0);
      break;
    }
    i = static_cast<std::size_t> (next - steps.begin ());
  }
  // The faces in rotation order: on each triangle of X, the one looking back (b -> a) if the
  // outside is behind it, then the one looking on (a -> b) if the outside is ahead (the
  // tetrahedra (a, b, c, d) are positively oriented). Directions alternate around the edge.
  const auto faceOn = [&] (SimplexId t, std::uint32_t from, std::uint32_t to) {
    for (std::uint32_t f : faces_here)
      if (faces[f].triangle == t && traverses (faces[f], from, to))
        return f;
    throw std::logic_error ("splitPinches: no face where the rotation around an edge expects one");
  };
  const std::size_t m = triangle.size ();
  std::vector<std::uint32_t>& around = scratch.around;
  around.clear ();
  for (std::size_t i = 0; i < m; ++i)
    if (x.contains ({2, triangle[i]}))
    {
      if (!gap_in_x[(i + m - 1) % m])
        around.push_back (faceOn (triangle[i], b, a));
      if (!gap_in_x[i])
        around.push_back (faceOn (triangle[i], a, b));
    }
  // Rotate so that the list starts with a face looking back: X (a tetrahedron, or a sheet
  // triangle's zero thickness) lies ahead of it, so pairs (0,1), (2,3)... are across X, and
  // pairs (1,2), ..., (2k-1,0) across the outside.
  if (!around.empty () && !traverses (faces[around[0]], b, a))
    std::rotate (around.begin (), around.begin () + 1, around.end ());
}

/** Glues the \a k2 faces \a around a pinch edge (in rotation order, facesAroundEdge()) pairwise.
  * First each face is glued to the one across the outside, as on the boundary of a thickened X:
  * parts of X that touch along the edge stay joined there, and a sheet continues through the
  * edge with one face per side. \a choice 1 glues each face to the one across X instead (the
  * parts come apart, a sheet folds back on itself), and higher choices every other way to glue
  * them without crossing. */
template <class Glue>
void
glueAroundEdge (const std::uint32_t* around, int k2, unsigned choice, const Glue& glue)
{
  // The pair from face i (even) across X, or from face i + 1 across the outside.
  const auto pairAt = [k2] (int i, bool across_x) {
    return across_x ? std::pair<int, int> (i, i + 1) : std::pair<int, int> (i + 1, (i + 2) % k2);
  };
  if (choice < 2) // glued at once, without listing every pairing
  {
    for (int i = 0; i < k2; i += 2)
    {
      const auto [f, g] = pairAt (i, choice == 1);
      glue (around[f], around[g]);
    }
    return;
  }
  std::vector<std::pair<int, int>> across_outside, across_x;
  for (int i = 0; i < k2; i += 2)
  {
    across_x.push_back (pairAt (i, true));
    across_outside.push_back (pairAt (i, false));
  }
  std::vector<std::vector<std::pair<int, int>>> choices = {across_outside, across_x};
  std::vector<int> open (k2);
  std::iota (open.begin (), open.end (), 0);
  std::vector<std::pair<int, int>> pairs;
  nonCrossingMatchings (open, pairs, choices, 64);
  for (const auto& [i, j] : choices[choice % choices.size ()])
    glue (around[i], around[j]);
}

/** What split() reads that does not depend on the choices: W's faces (a sheet triangle once per
  * side), their uses of each undirected edge, and the pinch edges (more than two faces), with the
  * faces around each of a 3-dimensional complex in rotation order. */
struct Faces
{
  std::vector<Face> faces;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> uses; // (edge key, face), ascending
  std::vector<std::size_t> manifold;                         // the first of an edge's two uses
  std::vector<std::pair<std::size_t, std::size_t>> pinches;  // [lo, hi) of uses, in ascending key order
  /** In a 3-dimensional complex, per pinch edge p its faces in rotation order (facesAroundEdge()):
    * around[around_begin[p] .. around_begin[p + 1]). */
  std::vector<std::size_t> around_begin;
  std::vector<std::uint32_t> around;
  std::size_t sheet_triangles = 0;
};

Faces
facesOf (const SimplicialComplex& complex, const Subcomplex& x, const Boundary& w)
{
  Faces out;
  std::vector<Face>& faces = out.faces;
  for (std::size_t i = 0; i < w.triangles.size (); ++i)
  {
    faces.push_back ({w.triangles[i], w.triangle_ids[i], false});
    if (x.cofaceCount ({2, w.triangle_ids[i]}) == 0)
    {
      faces.push_back ({{w.triangles[i][0], w.triangles[i][2], w.triangles[i][1]}, w.triangle_ids[i], true});
      ++out.sheet_triangles;
    }
  }

  // Faces by undirected edge.
  std::vector<std::pair<std::uint64_t, std::uint32_t>>& uses = out.uses;
  for (std::uint32_t f = 0; f < faces.size (); ++f)
    for (int i = 0; i < 3; ++i)
      uses.emplace_back (edgeKey (faces[f].v[i], faces[f].v[(i + 1) % 3]), f);
  std::sort (uses.begin (), uses.end ());

  // Pinch edges of a 3-dimensional complex need the tetrahedra around them: one scan collects them.
  std::vector<std::uint32_t> pinch_slot (complex.dimension () < 3 ? 0 : complex.size (1), NONE);
  for (std::size_t lo = 0, hi; lo < uses.size (); lo = hi)
  {
    for (hi = lo; hi < uses.size () && uses[hi].first == uses[lo].first; ++hi)
      ;
    const auto [a, b] = edgeEnds (uses[lo].first);
    const std::uint32_t f = uses[lo].second, g = uses[lo + 1 < hi ? lo + 1 : lo].second;
    if ((hi - lo) % 2 != 0 || (hi - lo == 2 && traverses (faces[f], a, b) == traverses (faces[g], a, b)))
      throw std::logic_error ("splitPinches: W is not closed at an edge");
    if (hi - lo == 2)
    {
      out.manifold.push_back (lo);
      continue;
    }
    if (complex.dimension () == 3)
    {
      const std::uint32_t* t = complex.vertices (2, faces[f].triangle);
      const unsigned mask =
          (t[0] == a || t[0] == b ? 1u : 0u) | (t[1] == a || t[1] == b ? 2u : 0u) | (t[2] == a || t[2] == b ? 4u : 0u);
      pinch_slot[complex.face (2, faces[f].triangle, mask).id] = static_cast<std::uint32_t> (out.pinches.size ());
    }
    out.pinches.emplace_back (lo, hi);
  }
  if (complex.dimension () == 3 && !out.pinches.empty ())
  {
    std::vector<std::vector<SimplexId>> tets_around (out.pinches.size ());
    for (SimplexId t = 0; t < complex.size (3); ++t)
      for (unsigned mask : {3u, 5u, 6u, 9u, 10u, 12u})
      {
        const std::uint32_t slot = pinch_slot[complex.face (3, t, mask).id];
        if (slot != NONE)
          tets_around[slot].push_back (t);
      }
    // The rotation around each pinch edge does not depend on the choices: found once.
    std::vector<std::uint32_t> here;
    AroundEdge scratch;
    out.around_begin.push_back (0);
    for (std::size_t p = 0; p < out.pinches.size (); ++p)
    {
      const auto [lo, hi] = out.pinches[p];
      const auto [a, b] = edgeEnds (uses[lo].first);
      here.clear ();
      for (std::size_t k = lo; k < hi; ++k)
        here.push_back (uses[k].second);
      facesAroundEdge (complex, x, a, b, tets_around[p], here, faces, scratch);
      std::vector<SimplexId> ().swap (tets_around[p]);
      out.around.insert (out.around.end (), scratch.around.begin (), scratch.around.end ());
      out.around_begin.push_back (out.around.size ());
    }
  }
  return out;
}

/** The faces \a in glued along every edge, each pinch edge the way \a choice says (see
  * glueAroundEdge), then one vertex per fan. */
ManifoldSplit
split (const SimplicialComplex& complex, const Faces& in, const std::vector<unsigned>& choice)
{
  ManifoldSplit out;
  const std::vector<Face>& faces = in.faces;
  const auto& uses = in.uses;
  out.sheet_triangles = in.sheet_triangles;
  out.pinch_edges = in.pinches.size ();
  UnionFind corners (3 * faces.size ()); // three per face: glued corners are one vertex
  const auto glueAlong = [&] (std::uint32_t a, std::uint32_t b) {
    return [&, a, b] (std::uint32_t f, std::uint32_t g) {
      for (std::uint32_t v : {a, b})
        corners.attach (3 * f + cornerOf (faces[f], v), 3 * g + cornerOf (faces[g], v));
    };
  };
  for (std::size_t lo : in.manifold)
  {
    const auto [a, b] = edgeEnds (uses[lo].first);
    glueAlong (a, b) (uses[lo].second, uses[lo + 1].second);
  }
  for (std::size_t p = 0; p < in.pinches.size (); ++p)
  {
    const auto [lo, hi] = in.pinches[p];
    const auto [a, b] = edgeEnds (uses[lo].first);
    const unsigned choice_here = choice[p];
    if (complex.dimension () < 3)
    {
      // Flat: every triangle is a sheet. Glue each side's two faces, so the sheet continues with
      // a top and a bottom; or fold each triangle back on itself.
      const bool fold = choice_here % 2 == 1;
      for (std::size_t k1 = lo; k1 < hi; ++k1)
        for (std::size_t k2 = k1 + 1; k2 < hi; ++k2)
        {
          const Face &f1 = faces[uses[k1].second], &f2 = faces[uses[k2].second];
          if (fold ? f1.triangle == f2.triangle : f1.reversed == f2.reversed && f1.triangle != f2.triangle)
            glueAlong (a, b) (uses[k1].second, uses[k2].second);
        }
      continue;
    }
    glueAroundEdge (&in.around[in.around_begin[p]], static_cast<int> (in.around_begin[p + 1] - in.around_begin[p]),
                    choice_here, glueAlong (a, b));
  }

  // One vertex per fan: the first fan met keeps the vertex, every other gets a copy.
  const std::uint32_t n = complex.numVertices ();
  std::vector<std::uint32_t> id_of_root (3 * faces.size (), NONE), first_root (n, NONE);
  std::vector<std::uint8_t> split_vertex (n, 0);
  out.triangles.resize (faces.size ());
  for (std::uint32_t f = 0; f < faces.size (); ++f)
    for (int i = 0; i < 3; ++i)
    {
      const std::uint32_t v = faces[f].v[i], root = corners.find (3 * f + i);
      if (id_of_root[root] == NONE)
      {
        if (first_root[v] == NONE)
        {
          first_root[v] = root;
          id_of_root[root] = v;
        }
        else
        {
          id_of_root[root] = n + static_cast<std::uint32_t> (out.copy_of.size ());
          out.copy_of.push_back (v);
          out.pinch_vertices += !split_vertex[v];
          split_vertex[v] = 1;
        }
      }
      out.triangles[f][i] = id_of_root[root];
    }
  return out;
}

} // namespace

std::uint64_t
edgeKey (std::uint32_t a, std::uint32_t b)
{
  return (std::uint64_t (std::min (a, b)) << 32) | std::max (a, b);
}

namespace
{

/** The undirected keys of the edges in \a directed (each directed edge of some triangles, as
  * (from << 32) | to) on which those triangles are not a 2-manifold: an edge traversed twice the
  * same way, or one way only. */
std::vector<std::uint64_t>
badEdges (std::vector<std::uint64_t>& directed)
{
  std::vector<std::uint64_t> bad;
  std::sort (directed.begin (), directed.end ());
  for (std::size_t i = 0; i < directed.size (); ++i)
  {
    const std::uint64_t reverse = (directed[i] << 32) | (directed[i] >> 32);
    if ((i + 1 < directed.size () && directed[i + 1] == directed[i]) ||
        !std::binary_search (directed.begin (), directed.end (), reverse))
      bad.push_back (std::min (directed[i], reverse));
  }
  return bad;
}

/** nonManifoldEdges() of a split's triangles, of those edges alone that have an end whose
  * original vertex is flagged in \a near: every triangle on such an edge has that end. */
std::vector<std::uint64_t>
nonManifoldEdgesNear (const ManifoldSplit& split, std::uint32_t n, const std::vector<std::uint8_t>& near)
{
  const auto flagged = [&] (std::uint32_t v) { return near[v < n ? v : split.copy_of[v - n]] != 0; };
  std::vector<std::uint64_t> directed;
  for (const auto& t : split.triangles)
    for (int i = 0; i < 3; ++i)
      if (flagged (t[i]) || flagged (t[(i + 1) % 3]))
        directed.push_back ((std::uint64_t (t[i]) << 32) | t[(i + 1) % 3]);
  return badEdges (directed);
}

} // namespace

std::vector<std::uint64_t>
nonManifoldEdges (const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint64_t> directed;
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i)
      directed.push_back ((std::uint64_t (t[i]) << 32) | t[(i + 1) % 3]);
  return badEdges (directed);
}

ManifoldSplit
splitPinches (const SimplicialComplex& complex, const Subcomplex& x, const Boundary& w)
{
  // Gluing across the outside keeps the parts of X that touch along an edge joined; but where the
  // outside, pulled apart there, still meets itself around both ends of the edge (two pockets of
  // the outside that touch only along it), the two pulled-apart copies of the edge join the same
  // two vertices. Around those ends X cannot also meet itself (on a small sphere around a vertex,
  // X and the outside cannot both join up across the same point), so gluing that edge across X
  // instead separates them. Flip the edges that need it until none does.
  // Where several pinch edges meet at a vertex, their gluings interact, and an edge with more
  // than four faces has more ways to be glued: an edge still bad tries its next way. A few
  // rounds settle every input tried; the bound guards against cycling.
  // A round changes the gluing only at the two ends of the edges it flips; elsewhere the surface
  // is the same as before, and as much a 2-manifold: the next round checks near those ends alone.
  const Faces faces = facesOf (complex, x, w); // the same in every round
  const std::uint32_t n = complex.numVertices ();
  std::vector<unsigned> choice (faces.pinches.size (), 0);
  std::vector<std::uint8_t> flipped_at; // per vertex: an end of an edge the last round flipped
  for (int round = 0; round < 64; ++round)
  {
    ManifoldSplit out = split (complex, faces, choice);
    const std::vector<std::uint64_t> bad =
        round == 0 ? nonManifoldEdges (out.triangles) : nonManifoldEdgesNear (out, n, flipped_at);
    if (bad.empty ())
      return out;
    const auto original = [&] (std::uint32_t v) { return v < n ? v : out.copy_of[v - n]; };
    std::vector<std::size_t> to_change;
    for (std::uint64_t e : bad)
    {
      const auto [u, v] = edgeEnds (e);
      const std::uint64_t key = edgeKey (original (u), original (v));
      const auto keyOf = [&] (const std::pair<std::size_t, std::size_t>& pinch) {
        return faces.uses[pinch.first].first;
      };
      const auto it = std::lower_bound (faces.pinches.begin (), faces.pinches.end (), key,
                                        [&] (const auto& pinch, std::uint64_t k) { return keyOf (pinch) < k; });
      if (it == faces.pinches.end () || keyOf (*it) != key)
        throw std::logic_error ("splitPinches: a non-manifold edge that is not a pinch edge");
      to_change.push_back (static_cast<std::size_t> (it - faces.pinches.begin ()));
    }
    std::sort (to_change.begin (), to_change.end ());
    to_change.erase (std::unique (to_change.begin (), to_change.end ()), to_change.end ());
    flipped_at.assign (n, 0);
    for (std::size_t i : to_change)
    {
      ++choice[i];
      for (std::uint32_t v : edgeEnds (faces.uses[faces.pinches[i].first].first))
        flipped_at[v] = 1;
    }
  }
  throw std::logic_error ("splitPinches: the split surface is not a 2-manifold");
}

} // namespace pcl_wrap::detail
