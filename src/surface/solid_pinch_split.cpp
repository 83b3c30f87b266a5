// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_pinch_split.h"

#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

/** A surface triangle seen from the solid: facet i of the solid tetrahedron t. */
struct Face
{
  std::uint32_t t;
  int i;
};

/** One pinched vertex's fans: the triangles of every fan but the first, by fan. */
struct Fans
{
  std::vector<std::vector<SimplexId>> copied; // fan k + 1's triangle ids
  std::vector<std::uint32_t> pinch_edges_to;  // w for each edge (v, w) with more than two triangles
};

class StarOfVertex
{
public:
  StarOfVertex (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
    : tetrahedra_ (tetrahedra), complex_ (tetrahedra.complex ()), inside_ (inside)
  {}

  /** The fans of the surface triangles around \a v. Two
    * triangles along an edge (v, w) are in one fan when a run of outside tetrahedra around the
    * edge joins them, or for the pinch edges in \a across_solid (sorted keys), a run of solid
    * ones. */
  Fans fans (std::uint32_t v, const std::vector<std::uint64_t>& across_solid) const
  {
    std::vector<Face> faces;
    std::unordered_map<std::uint64_t, std::uint32_t> face_at; // 4 t + i -> index in faces
    std::unordered_map<std::uint32_t, std::size_t> uses;      // w -> triangles on the edge (v, w)
    Star star;
    tetrahedra_.gatherStar (v, star);
    for (std::uint32_t t : star.tetrahedra ())
      for (int i = 0; i < 4; ++i)
        if (inside_[t] && complex_.vertex (3, t, i) != v && !solid (tetrahedra_.neighbour (t, i)))
        {
          face_at.emplace (4 * std::uint64_t (t) + i, static_cast<std::uint32_t> (faces.size ()));
          faces.push_back ({t, i});
          for (int j = 0; j < 4; ++j)
            if (j != i && complex_.vertex (3, t, j) != v)
              ++uses[complex_.vertex (3, t, j)];
        }
    UnionFind fan (faces.size ());
    for (std::uint32_t f = 0; f < faces.size (); ++f)
      for (int j = 0; j < 4; ++j)
      {
        const std::uint32_t w = complex_.vertex (3, faces[f].t, j);
        if (j == faces[f].i || w == v)
          continue;
        const bool through_solid =
            uses[w] == 2 || std::binary_search (across_solid.begin (), across_solid.end (), edgeKey (v, w));
        const Face g = through_solid ? acrossTheSolid (faces[f], v, w) : acrossTheOutside (faces[f], v, w);
        fan.attach (f, face_at.at (4 * std::uint64_t (g.t) + g.i));
      }
    // Fans in the order of their lowest triangle ids: the first keeps v.
    std::vector<std::pair<SimplexId, std::uint32_t>> by_id; // triangle id, face
    for (std::uint32_t f = 0; f < faces.size (); ++f)
      by_id.emplace_back (complex_.facet (3, faces[f].t, faces[f].i).id, f);
    std::sort (by_id.begin (), by_id.end ());
    std::unordered_map<std::uint32_t, std::size_t> fan_of_root;
    Fans out;
    for (const auto& [id, f] : by_id)
    {
      const auto [at, is_new] = fan_of_root.emplace (fan.find (f), fan_of_root.size ());
      if (at->second == 0)
        continue;
      if (is_new)
        out.copied.emplace_back ();
      out.copied[at->second - 1].push_back (id);
    }
    for (const auto& [w, count] : uses)
      if (count > 2)
        out.pinch_edges_to.push_back (w);
    return out;
  }

private:
  bool solid (std::uint32_t t) const { return t != OUTSIDE_HULL && inside_[t]; }

  /** From the surface triangle \a f, around its edge (v, w) through solid tetrahedra to the
    * surface triangle that ends the run. */
  Face acrossTheSolid (Face f, std::uint32_t v, std::uint32_t w) const
  {
    for (Face at = f;;)
    {
      const int out = tetrahedra_.otherFacetRoundEdge (at.t, at.i, v, w);
      const std::uint32_t u = tetrahedra_.neighbour (at.t, out);
      if (!solid (u))
        return {at.t, out};
      at = {u, tetrahedra_.mirrorIndex (at.t, out)};
    }
  }

  /** From the surface triangle \a f, around its edge (v, w) through outside tetrahedra to the
    * surface triangle that ends the run. The hull does not end it: the run goes on from the
    * edge's other hull facet, as through one more tetrahedron outside. */
  Face acrossTheOutside (Face f, std::uint32_t v, std::uint32_t w) const
  {
    std::uint32_t t = f.t;
    int leave = f.i;
    for (;;)
    {
      const std::uint32_t u = tetrahedra_.neighbour (t, leave);
      if (u == OUTSIDE_HULL)
      {
        // The other way round the edge from f, through every tetrahedron, to the hull again;
        // from there back towards f, where the run goes on.
        t = f.t;
        leave = tetrahedra_.otherFacetRoundEdge (f.t, f.i, v, w);
        for (std::uint32_t next; (next = tetrahedra_.neighbour (t, leave)) != OUTSIDE_HULL;)
        {
          leave = tetrahedra_.otherFacetRoundEdge (next, tetrahedra_.mirrorIndex (t, leave), v, w);
          t = next;
        }
        if (inside_[t])
          return {t, leave};
        leave = tetrahedra_.otherFacetRoundEdge (t, leave, v, w);
        continue;
      }
      const int back = tetrahedra_.mirrorIndex (t, leave);
      if (inside_[u])
        return {u, back};
      leave = tetrahedra_.otherFacetRoundEdge (u, back, v, w);
      t = u;
    }
  }

  const Tetrahedra& tetrahedra_;
  const SimplicialComplex& complex_;
  const std::vector<std::uint8_t>& inside_;
};

} // namespace

std::optional<ManifoldSplit>
splitSolidPinches (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside, const Boundary& w,
                   const std::vector<std::uint32_t>& pinched)
{
  const std::uint32_t n = tetrahedra.complex ().numVertices ();
  std::vector<std::uint32_t> vertices (pinched);
  std::sort (vertices.begin (), vertices.end ());
  vertices.erase (std::unique (vertices.begin (), vertices.end ()), vertices.end ());
  std::vector<std::uint32_t> slot_of (n, NONE);
  for (std::uint32_t s = 0; s < vertices.size (); ++s)
    slot_of[vertices[s]] = s;
  const StarOfVertex stars (tetrahedra, inside);
  const auto at_pinch = [&] (std::uint32_t v) { return v >= n || slot_of[v] != NONE; };
  std::vector<std::uint8_t> near_pinch (w.triangles.size (), 0);
  parallelForEach (w.triangles.size (), [&] (std::size_t k) {
    const auto& t = w.triangles[k];
    near_pinch[k] = slot_of[t[0]] != NONE || slot_of[t[1]] != NONE || slot_of[t[2]] != NONE;
  });

  // Pinch edges are glued across the outside first; one whose two copies still join the same two
  // vertices (two pockets of the outside that touch only along it) is glued across the solid
  // instead, until none is, as splitPinches() does.
  std::vector<std::uint64_t> across_solid;
  for (int round = 0; round < 8; ++round)
  {
    std::vector<Fans> fans (vertices.size ());
    parallelForEach (vertices.size (), [&] (std::size_t s) { fans[s] = stars.fans (vertices[s], across_solid); }, 1);
    ManifoldSplit out;
    std::vector<std::array<std::uint32_t, 3>> copies; // triangle id, vertex, its copy
    std::vector<std::uint64_t> pinch_edges;
    for (std::uint32_t s = 0; s < vertices.size (); ++s)
    {
      for (std::uint32_t to : fans[s].pinch_edges_to)
        pinch_edges.push_back (edgeKey (vertices[s], to));
      out.pinch_vertices += !fans[s].copied.empty ();
      for (const std::vector<SimplexId>& fan : fans[s].copied)
      {
        const std::uint32_t copy = n + static_cast<std::uint32_t> (out.copy_of.size ());
        out.copy_of.push_back (vertices[s]);
        for (SimplexId id : fan)
          copies.push_back ({id, vertices[s], copy});
      }
    }
    std::sort (copies.begin (), copies.end ());
    std::sort (pinch_edges.begin (), pinch_edges.end ());
    pinch_edges.erase (std::unique (pinch_edges.begin (), pinch_edges.end ()), pinch_edges.end ());
    out.pinch_edges = pinch_edges.size ();

    // The triangles, each pinched vertex replaced by the copy of its fan.
    out.triangles = w.triangles;
    parallelForEach (w.triangles.size (), [&] (std::size_t k) {
      if (!near_pinch[k])
        return;
      const SimplexId id = w.triangle_ids[k];
      for (auto at = std::lower_bound (copies.begin (), copies.end (), std::array<std::uint32_t, 3>{id, 0, 0});
           at != copies.end () && (*at)[0] == id; ++at)
        std::replace (out.triangles[k].begin (), out.triangles[k].end (), (*at)[1], (*at)[2]);
    });

    // Each edge at a pinched vertex or its copies in two triangles, once each way.
    std::vector<std::array<std::uint32_t, 3>> near;
    for (std::size_t k = 0; k < out.triangles.size (); ++k)
      if (near_pinch[k])
        near.push_back (out.triangles[k]);
    const auto original = [&] (std::uint32_t v) { return v < n ? v : out.copy_of[v - n]; };
    std::vector<std::uint64_t> bad;
    for (std::uint64_t e : nonManifoldEdges (near))
    {
      const auto a = std::uint32_t (e >> 32), b = std::uint32_t (e); // other edges end at the patch's rim
      if (at_pinch (a) || at_pinch (b))
        bad.push_back (edgeKey (original (a), original (b)));
    }
    if (bad.empty ())
      return out;
    for (std::uint64_t e : bad)
      if (!std::binary_search (pinch_edges.begin (), pinch_edges.end (), e) ||
          std::binary_search (across_solid.begin (), across_solid.end (), e))
        return std::nullopt; // both ways tried: more than two ways to glue
    across_solid.insert (across_solid.end (), bad.begin (), bad.end ());
    std::sort (across_solid.begin (), across_solid.end ());
    across_solid.erase (std::unique (across_solid.begin (), across_solid.end ()), across_solid.end ());
  }
  return std::nullopt;
}

} // namespace pcl_wrap::detail
