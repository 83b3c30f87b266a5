// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The vertices of a closed surface near which it has a small handle, and their patches. */
struct SmallHandlePatches
{
  std::vector<std::uint32_t> centres; ///< ascending vertex ids
  /** Per centre: its patch goes round a thin tube between two wider parts of the surface, past
    * both of whose ends the surface opens out: a tunnel through a wall (the tube hollow), to be
    * filled, or a web across a gap (the tube solid), to be cut where the gap is one the sampling
    * resolves. */
  std::vector<std::uint8_t> tunnel;
  /** Per centre: its patch, on a part of genus 0, goes round a thin tube whose two ends the rest
    * of the surface does not join near, past at most one of which it opens out: a web that is the
    * last tie between two small objects, but also a finger or a tail, which the points sample
    * along their length. Its webs alone are candidates, as a tunnel's. */
  std::vector<std::uint8_t> neck;
  /** The patch around centres[i]: the vertices vertices[begin[i] .. begin[i + 1]), ascending. */
  std::vector<std::uint32_t> begin, vertices;
  /** Per vertex of a tunnel's or a neck's patch, how much nearer it is to one end of the tube
    * than to the other: its rings within the patch from one of the patch's two boundary loops
    * (past which the surface opens out, for a tunnel), less its rings from the other. A tube's cross-sections lie between two levels.
    * 0 for the other patches' vertices. */
  std::vector<std::int8_t> level;
  /** smallHandlePatches(): whether some part of the surface has a genus (a vertex where it
    * touches itself counted once per fan), near the vertices looked at or not. wideTunnelPatches()
    * leaves it false. */
  bool has_genus = false;
};

/** \brief The vertices of a closed surface near which it has a small handle: a handle whose tube
  * a few rings of triangles around the vertex go round.
  *
  * The connected parts of the surface (its triangles joined where they share an edge, so that
  * surfaces touching at a vertex are parts of their own) whose genus (from the Euler
  * characteristic, V - F / 2 for a closed surface, a vertex where a part touches itself counted
  * once per fan of triangles there) is above zero are looked at; given the vertices' positions, so
  * are the sharp saddles of the parts of genus 0 that touch nothing at a vertex, and their
  * neighbours, where a thin tube may join two wider parts (a bridge between two objects). The
  * angles of the triangles at a vertex add up to 2 pi less the surface's curvature there; a tube
  * that joins two closed surfaces into one takes 4 pi of curvature away (Gauss-Bonnet), about 2 pi
  * where each of its ends meets a wider part, and on a tube a few triangles across that lies on a
  * few vertices, whose angles add up to more than 2 pi + SADDLE_EXCESS. On a sampled surface,
  * smooth or noisy, few vertices do. The centres are a maximal independent set of the vertices
  * looked at (each is one or next to one). Around a centre, the triangles within HANDLE_RINGS rings
  * make a patch; it is a disc where the surface has no small handle. Where it is not, it holds a
  * handle (its own genus is above zero, a boundary vertex where it touches itself counted once per
  * fan of its triangles there), or it goes round a thin tube: a handle's when the rest of the
  * surface joins the patch's boundary loops near the patch (within twice as many rings again), a
  * thin part's (a finger, a tail) when a loop cuts a part off, a tunnel's when the surface opens
  * out past both ends (a hole through a wall, a web across a gap), a ring's when it does not (the
  * tube closes far away). On a part of genus 0, a tube with two boundary loops that the rest of the
  * surface does not join near is a neck (SmallHandlePatches::neck) where it does not open out past
  * both: the last tie between two small objects, or a finger.
  * \param[in] triangles a closed surface's, vertex ids below \a num_vertices
  * \param[in] near if given, only centres within 2 HANDLE_RINGS rings of one of these vertices
  * \param[in] positions if given, per vertex: the parts of genus 0 are looked at near sharp saddles */
SmallHandlePatches
smallHandlePatches (const std::vector<std::array<std::uint32_t, 3>>& triangles, std::uint32_t num_vertices,
                    const std::vector<std::uint32_t>* near = nullptr,
                    const std::vector<std::array<double, 3>>* positions = nullptr);

/** \brief How far above 2 pi the angles at a sharp saddle add up (smallHandlePatches()): the end
  * of a tube four vertices around, where it meets a plane at a right angle (a quarter of 2 pi on
  * each), is not quite one. The thin webs the labelling leaves across a gap between two objects
  * end on two to four vertices. */
constexpr double SADDLE_EXCESS = 0.5 * 3.14159265358979323846;

/** \brief How many rings of triangles around a vertex smallHandlePatches() looks at. */
constexpr int HANDLE_RINGS = 3;

/** \brief The tunnels of a closed surface whose tube a patch of WIDE_TUNNEL_RINGS rings goes
  * round: smallHandlePatches()'s tunnels, from wider patches, centred on the sharp saddles of the
  * parts of genus above zero (a tunnel's tube ends on some, as a web's does), on a part only where
  * at most one vertex in WIDE_TUNNEL_SADDLE_SHARE is one. A slit through a thin wall, a few
  * spacings long, is too long for a patch of HANDLE_RINGS rings to go round.
  * \param[in] triangles a closed surface's, vertex ids below \a num_vertices
  * \param[in] positions per vertex */
SmallHandlePatches
wideTunnelPatches (const std::vector<std::array<std::uint32_t, 3>>& triangles, std::uint32_t num_vertices,
                   const std::vector<std::array<double, 3>>& positions);

/** \brief How many rings of triangles around a vertex wideTunnelPatches() looks at. */
constexpr int WIDE_TUNNEL_RINGS = 2 * HANDLE_RINGS;

/** \brief wideTunnelPatches() looks at a part's sharp saddles only when at most one of its
  * vertices in this many is one: they mark the ends of tubes on a smooth surface, which has few
  * (one vertex in 500 of a torus with noise of a quarter spacing; one in 28 to 50 of a torus, a
  * mug or a helmet with noise of half a spacing), not where noise makes them common (one vertex in
  * nine with noise of a spacing). */
constexpr long WIDE_TUNNEL_SADDLE_SHARE = 16;

} // namespace pcl_wrap::detail
