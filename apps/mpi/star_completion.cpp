// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "star_completion.h"

#include "message_exchange.h"
#include "tile_search.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
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

/** A question to another tile: may one of your points be in this reach of my tetrahedron? */
struct Question
{
  TileReach reach;
  std::uint32_t tetrahedron; ///< in the asker's triangulation of this round
  std::int32_t from;
};

/** A yes: one of the answerer's points may be in the reach of that tetrahedron. */
struct Answer
{
  std::uint32_t tetrahedron;
  std::int32_t tile;
};

/** A tetrahedron (its vertices' indices, ascending) and a tile it asked: asked once for good,
  * since the tile's own points never change. */
struct Asked
{
  std::array<std::uint32_t, 4> vertices;
  std::int32_t tile;
  bool operator== (const Asked& o) const { return vertices == o.vertices && tile == o.tile; }
};

struct AskedHash
{
  std::size_t operator() (const Asked& a) const
  {
    std::uint64_t h = static_cast<std::uint64_t> (a.tile);
    for (std::uint32_t v : a.vertices)
      h = (h ^ v) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t> (h ^ (h >> 29));
  }
};

/** Sends every rank its \a questions and answers theirs from \a search; returns the yeses
  * this rank's questions got. */
std::vector<Answer>
answers (MPI_Comm comm, const std::vector<std::vector<Question>>& questions, TileSearch& search)
{
  int rank = 0;
  MPI_Comm_rank (comm, &rank);
  const std::vector<Question> received = allToAll (comm, questions);
  std::vector<const TileReach*> reaches (received.size ());
  for (std::size_t i = 0; i < received.size (); ++i)
    reaches[i] = &received[i].reach;
  const std::vector<std::uint8_t> yes = search.anyMayBeIn (reaches);
  std::vector<std::vector<Answer>> out (questions.size ());
  for (std::size_t i = 0; i < received.size (); ++i)
    if (yes[i])
      out[received[i].from].push_back ({received[i].tetrahedron, rank});
  return allToAll (comm, out);
}

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
  std::vector<Point3> own (tile.own);
  for (std::size_t i = 0; i < tile.own; ++i)
    own[i] = tile.points[i].position;
  TileSearch search (std::move (own));
  std::unordered_set<Asked, AskedHash> asked;
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
    const auto askedKey = [&] (const std::uint32_t* v, int s) {
      Asked key{{record (v[0]).index, record (v[1]).index, record (v[2]).index, record (v[3]).index}, s};
      std::sort (key.vertices.begin (), key.vertices.end ());
      return key;
    };
    std::vector<std::vector<Question>> questions (ranks);
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
      // Per tetrahedron and tile s: all its vertices when it has one of s's (s learns its points'
      // neighbours here); a question to s when it is on own points only and may reach s's box.
      // Gathered on all threads, sent in order.
      std::vector<std::vector<std::pair<std::uint32_t, int>>> whole (count == 0 ? 0 : (count + 4095) / 4096);
      std::vector<std::vector<std::vector<Question>>> asking (whole.size ());
      tbb::parallel_for (std::size_t (0), whole.size (), [&] (std::size_t block) {
        asking[block].resize (ranks);
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
            bool has_theirs = false;
            for (int i = 0; i < 4; ++i)
              has_theirs |= record (v[i]).tile == static_cast<std::uint32_t> (s);
            if (has_theirs)
            {
              whole[block].push_back ({static_cast<std::uint32_t> (t), s});
              continue;
            }
            if (!has_own || asked.count (askedKey (v, s)))
              continue;
            if (!ball)
              ball = TileReach::ofTetrahedron (p, w, w_max);
            const auto id = static_cast<std::uint32_t> (t);
            if (ball->mayMeet (boxes[s]))
              asking[block][s].push_back ({*ball, id, rank});
            for (int i = 0; i < 4; ++i) // hull facets: their half-spaces
              if (triangulation.neighbours[4 * t + i] == detail::NO_NEIGHBOUR)
              {
                const std::array<Point3, 3> facet{p[(i + 1) % 4], p[(i + 2) % 4], p[(i + 3) % 4]};
                const TileReach beyond = TileReach::ofHullFacet (facet, p[i]);
                if (beyond.mayMeet (boxes[s]))
                  asking[block][s].push_back ({beyond, id, rank});
              }
          }
        }
      });
      for (const auto& block : whole)
        for (const auto& [t, s] : block)
          for (int i = 0; i < 4; ++i)
            outboxes.send (s, record (triangulation.top_simplices[4 * std::size_t (t) + i]));
      // The questions: may one of your points be in this reach? Only the own vertices of a
      // tetrahedron answered yes go to the tile that answered.
      for (auto& block : asking)
        for (int s = 0; s < ranks; ++s)
        {
          for (const Question& q : block[s])
            asked.insert (askedKey (&triangulation.top_simplices[4 * std::size_t (q.tetrahedron)], s));
          questions[s].insert (questions[s].end (), block[s].begin (), block[s].end ());
        }
      asking = {};
      for (const auto& box : questions)
        statistics.questions += box.size ();
    }
    // Every rank asks and answers, the flat ones with nothing: the exchanges are collective.
    for (const Answer& a : answers (comm, questions, search))
      for (int i = 0; i < 4; ++i)
      {
        const PointRecord& r = record (triangulation.top_simplices[4 * std::size_t (a.tetrahedron) + i]);
        if (r.tile == static_cast<std::uint32_t> (rank))
          outboxes.send (a.tile, r);
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
    statistics.by_nearest = search.byNearest ();
    if (sumOverRanks (comm, added) == 0)
      return triangulation;
  }
}

} // namespace pcl_wrap::mpi
