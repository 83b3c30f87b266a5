// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "star_completion.h"

#include "message_exchange.h"

#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <optional>
#include <unordered_set>

namespace pcl_wrap::mpi
{
namespace
{

/** Per rank: the points to send it, each once over all rounds. */
class Outboxes
{
public:
  explicit Outboxes (int ranks) : boxes_ (ranks), sent_ (ranks) {}

  void send (int rank, const PointRecord& p)
  {
    if (p.tile != static_cast<std::uint32_t> (rank) && sent_[rank].insert (p.index).second)
      boxes_[rank].push_back (p);
  }
  std::vector<std::vector<PointRecord>> take ()
  {
    return std::exchange (boxes_, std::vector<std::vector<PointRecord>> (boxes_.size ()));
  }

private:
  std::vector<std::vector<PointRecord>> boxes_;
  std::vector<std::unordered_set<std::uint32_t>> sent_;
};

} // namespace

detail::Triangulation
completeStars (MPI_Comm comm, TilePoints& tile, const std::vector<Box>& boxes, double w_max, bool equal_weights,
               StarCompletionStatistics& statistics)
{
  int ranks = 0, rank = 0;
  MPI_Comm_size (comm, &ranks);
  MPI_Comm_rank (comm, &rank);
  std::unordered_set<std::uint32_t> held;
  for (const PointRecord& p : tile.points)
    held.insert (p.index);
  Outboxes outboxes (ranks);
  // Each round inserts only what the last one brought.
  detail::GrowingTriangulation growing (equal_weights);
  std::vector<Point3> positions;
  std::vector<double> weights;
  for (;;)
  {
    ++statistics.rounds;
    const std::size_t first = positions.size ();
    for (std::size_t i = first; i < tile.points.size (); ++i)
    {
      positions.push_back (tile.points[i].position);
      weights.push_back (tile.points[i].weight);
    }
    growing.insert (positions, weights, first);
    detail::Triangulation triangulation = growing.read (positions);
    const auto record = [&] (std::uint32_t vertex) -> const PointRecord& {
      return tile.points[triangulation.point_of_vertex[vertex]];
    };
    if (triangulation.dimension < 3)
    {
      // Flat so far: no ball to bound. Every point goes to every tile (it may be the whole S
      // that is flat); what comes back makes the next round's triangulation solid if S is.
      for (int s = 0; s < ranks; ++s)
        if (s != rank && !boxes[s].empty)
          for (std::size_t i = 0; i < tile.own; ++i)
            outboxes.send (s, tile.points[i]);
    }
    else
    {
      const std::size_t count = triangulation.top_simplices.size () / 4;
      // Per tetrahedron, the ranks it goes to and whether with all its vertices or only the
      // own ones; gathered on all threads, sent in order.
      struct Sending
      {
        std::uint32_t tetrahedron;
        int rank;
        bool all_vertices;
      };
      std::vector<std::vector<Sending>> found (count == 0 ? 0 : (count + 4095) / 4096);
      tbb::parallel_for (std::size_t (0), found.size (), [&] (std::size_t block) {
        for (std::size_t t = 4096 * block; t < std::min (count, 4096 * (block + 1)); ++t)
        {
          const std::uint32_t* v = &triangulation.top_simplices[4 * t];
          bool has_own = false;
          std::array<Point3, 4> p;
          std::array<double, 4> w;
          for (int i = 0; i < 4; ++i)
          {
            const PointRecord& r = record (v[i]);
            has_own |= r.tile == static_cast<std::uint32_t> (rank);
            p[i] = r.position;
            w[i] = r.weight;
          }
          std::optional<TileReach> ball;
          for (int s = 0; s < ranks; ++s)
          {
            if (s == rank)
              continue;
            // On a point of tile s: s gets the point's neighbours here (its ball holds the point,
            // so it meets s's box).
            bool has_theirs = false;
            for (int i = 0; i < 4; ++i)
              has_theirs |= record (v[i]).tile == static_cast<std::uint32_t> (s);
            if (has_theirs)
            {
              found[block].push_back ({static_cast<std::uint32_t> (t), s, true});
              continue;
            }
            if (!has_own)
              continue;
            // On own points only: s gets them if the tetrahedron may reach into s's box.
            if (!ball)
              ball = TileReach::ofTetrahedron (p, w, w_max);
            bool meets = ball->mayMeet (boxes[s]);
            for (int i = 0; i < 4 && !meets; ++i) // hull facets: their half-spaces
              if (triangulation.neighbours[4 * t + i] == detail::NO_NEIGHBOUR)
              {
                const std::array<Point3, 3> facet{p[(i + 1) % 4], p[(i + 2) % 4], p[(i + 3) % 4]};
                meets = TileReach::ofHullFacet (facet, p[i]).mayMeet (boxes[s]);
              }
            if (meets)
              found[block].push_back ({static_cast<std::uint32_t> (t), s, false});
          }
        }
      });
      for (const auto& block : found)
        for (const Sending& send : block)
          for (int i = 0; i < 4; ++i)
          {
            const PointRecord& r = record (triangulation.top_simplices[4 * std::size_t (send.tetrahedron) + i]);
            if (send.all_vertices || r.tile == static_cast<std::uint32_t> (rank))
              outboxes.send (send.rank, r);
          }
    }
    const std::vector<std::vector<PointRecord>> sending = outboxes.take ();
    for (const auto& box : sending)
      statistics.bytes_sent += box.size () * sizeof (PointRecord);
    std::size_t added = 0;
    for (const PointRecord& p : allToAll (comm, sending))
      if (held.insert (p.index).second)
      {
        tile.points.push_back (p);
        ++added;
      }
    statistics.ghosts += added;
    if (sumOverRanks (comm, added) == 0)
      return triangulation;
  }
}

} // namespace pcl_wrap::mpi
