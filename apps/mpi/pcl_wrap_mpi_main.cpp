// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap_mpi: the Wrap over MPI ranks, each holding one tile of the points
// (docs/mpi.md).
#include "distributed_retraction.h"
#include "gathered_surface.h"
#include "message_exchange.h"
#include "star_completion.h"
#include "tile_complex.h"
#include "tile_input.h"
#include "tile_routing.h"
#include "tile_spacing.h"
#include "tile_wrap.h"

#include "mesh_file.h"
#include "point_file.h"
#include "threshold_option.h"
#include "wrap_report.h"

#include "delaunay/power_predicates.h"
#include "util/stage_clock.h"
#include "wrap/boundary.h"
#include "wrap/classification.h"
#include "wrap/subcomplex.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/statistics_json.h>
#include <pcl_wrap/version.h>

#include <mpi.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <iostream>
#include <string>
#include <vector>

using namespace pcl_wrap;

namespace
{

struct Options
{
  std::string input, output, stats_json, complex_json;
  bool raw = false, stats = false, quiet = false, weights_column = false;
  std::string weight_field;
  WrapParameters parameters; ///< the threshold and deletion mode
};

const char* const USAGE =
    "usage: mpirun -np K pcl_wrap_mpi INPUT OUTPUT [options]\n"
    "The Wrap computed by K MPI ranks, each holding one tile of the points; the output is the same\n"
    "as one process's. INPUT is a point file, or a folder of point files read in the order of\n"
    "their names as one (docs/mpi.md).\n"
    "  --raw                 the paper's W = Bd X, as pcl_wrap --raw (default: pcl_wrap's default\n"
    "                        surface, its surface stage run by rank 0 on the gathered tetrahedra)\n"
    "  --delta D, --radius R, --radius-rel K, --sinks J, --mode front|global\n"
    "                        wrap tighter, as pcl_wrap does (rank 0 deletes the sinks, as it runs\n"
    "                        the surface stage)\n"
    "  --stats               print what the construction did, per tile and in total\n"
    "  --stats-json FILE     the statistics as JSON, as pcl_wrap writes them\n"
    "  --complex FILE        the complex as JSON, as pcl_wrap --complex writes it (gathered on\n"
    "                        rank 0: for small inputs)\n"
    "  --weights-column      .xyz/.txt: the 4th column holds weights\n"
    "  --weight-field NAME   .pcd/.ply: the field holding weights\n"
    "  --quiet               nothing on stderr but errors\n"
    "  --version, -h/--help\n";

/** Parses the command line on every rank alike; a usage error ends the run with 2. */
bool
parseOptions (int argc, char** argv, Options& o, int rank, int& exit_code)
{
  const auto usageError = [&] (const std::string& message) {
    if (rank == 0)
      std::cerr << "pcl_wrap_mpi: " << message << " (see pcl_wrap_mpi --help)\n";
    exit_code = 2;
    return false;
  };
  std::vector<std::string> positional;
  int thresholds = 0;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&] (std::string& into) {
      if (i + 1 >= argc)
        return false;
      into = argv[++i];
      return true;
    };
    if (arg == "-h" || arg == "--help" || arg == "--version")
    {
      if (rank == 0)
        std::cout << (arg == "--version" ? std::string ("pcl_wrap_mpi ") + PCL_WRAP_VERSION + "\n" : USAGE);
      exit_code = 0;
      return false;
    }
    else if (arg == "--raw")
      o.raw = true;
    else if (apps::isThresholdOption (arg))
    {
      std::string v;
      if (!value (v))
        return usageError (arg + " needs a value");
      const std::string error = apps::applyThresholdOption (arg, v, o.parameters, thresholds);
      if (!error.empty ())
        return usageError (error);
    }
    else if (arg == "--stats")
      o.stats = true;
    else if (arg == "--quiet")
      o.quiet = true;
    else if (arg == "--weights-column")
      o.weights_column = true;
    else if (arg == "--stats-json" || arg == "--complex" || arg == "--weight-field")
    {
      std::string& into = arg == "--stats-json" ? o.stats_json : arg == "--complex" ? o.complex_json : o.weight_field;
      if (!value (into))
        return usageError (arg + " needs a value");
    }
    else if (arg.size () > 1 && arg[0] == '-')
      return usageError ("unknown option " + arg);
    else
      positional.push_back (arg);
  }
  if (positional.size () != 2)
    return usageError ("give an input file and an output file");
  if (o.parameters.threshold.deletes () && !o.complex_json.empty ())
    return usageError ("--complex lists X before a threshold's deletion: give one or the other");
  o.parameters.output = o.raw ? Output::raw : Output::surface;
  o.parameters.keep_complex = o.parameters.filtration = !o.complex_json.empty ();
  o.input = positional[0];
  o.output = positional[1];
  if (!apps::isMeshFormat (o.output))
    return usageError (o.output + ": the output must be .ply, .obj, .vtk, .off or .stl");
  std::error_code error;
  for (const std::string& written : {o.output, o.stats_json, o.complex_json})
    if (!written.empty () && std::filesystem::equivalent (written, o.input, error))
      return usageError (written + " is the input: it would be overwritten");
  return true;
}

/** Gathers the tiles' parts of W on rank 0, sheets turned as one process turns them. */
WrapSurface
gatheredW (MPI_Comm comm, const mpi::TileWrap& tile)
{
  WrapSurface w;
  w.triangles = mpi::gatherToRoot (comm, tile.faces);
  std::vector<std::array<std::uint32_t, 3>> sheets = mpi::gatherToRoot (comm, tile.sheets);
  detail::orientSheetTriangles (sheets, [] (std::uint32_t v) { return v; });
  w.triangles.insert (w.triangles.end (), sheets.begin (), sheets.end ());
  w.dangling_edges = mpi::gatherToRoot (comm, tile.dangling_edges);
  w.isolated_vertices = mpi::gatherToRoot (comm, tile.isolated_vertices);
  return w;
}

/** \a local of every rank on rank 0, sorted. */
template <class T>
std::vector<T>
gatheredSorted (MPI_Comm comm, const std::vector<T>& local)
{
  std::vector<T> all = mpi::gatherToRoot (comm, local);
  std::sort (all.begin (), all.end ());
  return all;
}

/** This process's peak resident memory so far. */
double
peakMegabytes ()
{
  rusage usage{};
  getrusage (RUSAGE_SELF, &usage);
  return static_cast<double> (usage.ru_maxrss) / 1024.0;
}

/** Rank 0's files: OUTPUT and, when asked, the complex and the statistics, as pcl_wrap writes
  * them for \a points (the whole input). */
void
writeOutputs (const Options& o, const apps::PointFile& points, const WrapResult& result)
{
  apps::writeSurfaceMesh (o.output, points, result);
  if (!o.complex_json.empty ())
    apps::writeAtomically (o.complex_json,
                           [&] (std::ostream& out) { apps::writeComplexJson (out, result, points.points.size ()); });
  if (!o.stats_json.empty ())
    apps::writeAtomically (o.stats_json, [&] (std::ostream& out) { out << statisticsJson (result) << '\n'; });
}

/** Points that span no volume (all on a plane or a line, or fewer than four): rank 0 wraps them
  * alone, as pcl_wrap does, and writes what it writes. The tiles' construction completes the
  * stars of tetrahedra, and Del S then has none; its triangles or edges are a small fraction of a
  * volume's simplices, which the other ranks would have held. */
int
wrapOnRoot (const Options& o, MPI_Comm comm, const mpi::InputSource& source, int dimension)
{
  int ranks = 0, rank = 0;
  MPI_Comm_size (comm, &ranks);
  MPI_Comm_rank (comm, &rank);
  if (rank != 0)
    return 0;
  const apps::PointFile points = source.readAll ();
  WrapParameters parameters = o.parameters;
  if (!parameters.viewpoint && points.viewpoint)
    parameters.viewpoint = *points.viewpoint;
  const WrapResult result = computeWrap (points.points, points.weights, parameters);
  writeOutputs (o, points, result);
  const std::string alone =
      "the points span no volume (Del S has dimension " + std::to_string (dimension) + "): rank 0 wrapped them alone";
  if (o.stats)
  {
    apps::printSummary (std::cout, result.statistics);
    std::cout << "tiles:         " << ranks << "; " << alone << "\n"
              << "peak memory:   " << static_cast<long> (peakMegabytes ()) << " MB (rank 0)\n";
  }
  if (!o.quiet)
    std::cerr << "pcl_wrap_mpi: wrote " << o.output << ": " << result.surface.triangles.size () << " triangles; "
              << alone << '\n';
  return 0;
}

int
run (const Options& o, MPI_Comm comm)
{
  int ranks = 0, rank = 0;
  MPI_Comm_size (comm, &ranks);
  MPI_Comm_rank (comm, &rank);
  WrapResult result;
  WrapStatistics& stats = result.statistics;
  const StageObserver no_observer;
  detail::StageClock clock (stats, no_observer);

  // Each rank reads a share of the input; the points then go to the tiles they fall in.
  const mpi::InputSource source{o.input, o.weight_field, o.weights_column};
  mpi::InputShare share = mpi::readShare (comm, source);
  const std::uint64_t points_input = share.total;
  result.skipped = gatheredSorted (comm, share.skipped);
  mpi::RoutedTile routed = mpi::routeToTiles (comm, std::move (share));
  for (const auto& [dropped, kept] : gatheredSorted (comm, routed.duplicates))
    result.duplicates.emplace_back (dropped, kept);
  const std::uint64_t points_kept = mpi::sumOverRanks (comm, routed.points.own);
  if (points_kept == 0)
    throw apps::FileError (o.input + ": no point with finite coordinates");
  mpi::TilePoints& tile = routed.points;
  clock.stageDone ("input");

  mpi::StarCompletionStatistics completion;
  int dimension = -1;
  std::vector<std::uint32_t> hidden; // own points with an empty power cell
  std::unique_ptr<mpi::TileComplex> part;
  {
    detail::Triangulation triangulation =
        mpi::completeStars (comm, tile, routed.boxes, routed.w_max, routed.equal_weights, completion);
    dimension = static_cast<int> (mpi::largestOverRanks (comm, triangulation.dimension));
    if (dimension < 3)
    {
      tile = {};
      triangulation = {};
      return wrapOnRoot (o, comm, source, dimension);
    }
    for (std::uint32_t h : triangulation.hidden)
      if (h < tile.own)
        hidden.push_back (tile.points[h].index);
    clock.stageDone ("triangulation");
    part = std::make_unique<mpi::TileComplex> (tile, triangulation, static_cast<std::uint32_t> (rank));
  }
  stats.spacing = mpi::tileMedianSpacing (comm, *part);
  tile = {};
  std::unique_ptr<detail::Classification> classification;
  {
    const detail::PowerPredicates predicates (part->positions (), part->weights ());
    classification = std::make_unique<detail::Classification> (detail::classify (part->complex (), predicates));
  }
  clock.stageDone ("classification");

  // The default surface, a threshold's deletion and the complex's listing (with its classes and
  // the wrap filtration) run on rank 0 from every tile's tetrahedra.
  const bool on_root = !o.raw || o.parameters.threshold.deletes () || o.parameters.keep_complex;
  mpi::TileSolid solid;
  std::vector<std::array<std::uint32_t, 3>> sheets;
  std::uint64_t collapses = 0, removals = 0;
  std::size_t retraction_rounds = 0;
  {
    detail::Subcomplex y (part->complex (), part->releaseCofaceCounts ());
    mpi::DistributedRetraction retraction (comm, *part, *classification, y);
    retraction.retract ();
    collapses = mpi::sumOverRanks (comm, retraction.collapses ());
    removals = mpi::sumOverRanks (comm, retraction.removalsSent ());
    retraction_rounds = retraction.rounds ();
    clock.stageDone ("retraction");

    const mpi::TileWrap wrap = mpi::extractTileWrap (*part, y);
    result.w = gatheredW (comm, wrap);
    result.surface = result.w;
    for (int k = 0; k <= 3; ++k)
      stats.x_simplices[k] = mpi::sumOverRanks (comm, wrap.x_count[k]);
    if (on_root)
    {
      sheets = mpi::gatherToRoot (comm, wrap.sheets);
      solid = mpi::tileSolid (*part, y);
    }
  }
  result.hidden = gatheredSorted (comm, hidden); // in input order, as one process lists them
  clock.stageDone ("boundary");

  // Statistics: counts summed over the tiles, each simplex counted by the tile it belongs to.
  std::array<std::uint64_t, 12> classes{};
  for (int k = 0; k <= 3; ++k)
    for (detail::SimplexId id = 0; id < part->complex ().size (k); ++id)
      if (part->belongsHere ({k, id}))
        ++classes[3 * k + static_cast<int> (classification->of ({k, id}))];
  for (int k = 0; k <= 3; ++k)
    for (int c = 0; c < 3; ++c)
      stats.simplices[k][c] = mpi::sumOverRanks (comm, classes[3 * k + c]);
  classification.reset ();
  part.reset ();
  if (on_root) // the tetrahedra to rank 0, which runs the stages above on them
  {
    solid.tetrahedra = mpi::gatherToRoot (comm, solid.tetrahedra);
    solid.in_x = mpi::gatherToRoot (comm, solid.in_x);
  }
  stats.points_input = points_input;
  stats.points_skipped = result.skipped.size ();
  stats.points_duplicate = result.duplicates.size ();
  stats.points_hidden = result.hidden.size ();
  stats.points_used = points_kept - mpi::sumOverRanks (comm, hidden.size ());
  stats.triangulation_dimension = dimension;
  stats.collapses = collapses;
  // Each stage's time is the slowest rank's: the others wait for it at the next exchange.
  for (StageTiming& t : stats.timings)
    t.seconds = mpi::largestOverRanks (comm, t.seconds);

  std::vector<double> peaks = mpi::gatherToRoot (comm, std::vector<double>{peakMegabytes ()});
  const std::size_t ghosts = mpi::sumOverRanks (comm, completion.ghosts);
  const std::size_t bytes = mpi::sumOverRanks (comm, completion.bytes_sent);
  const std::size_t questions = mpi::sumOverRanks (comm, completion.questions);
  const std::size_t by_nearest = mpi::sumOverRanks (comm, completion.by_nearest);
  if (rank != 0)
    return 0;

  // Rank 0 writes the one mesh, over every input point (read again, now that the tile's work is
  // done and freed), after running the surface stage on every tile's tetrahedra.
  const apps::PointFile points = source.readAll ();
  if (on_root)
    mpi::surfaceOnRoot (points, result.hidden, std::move (solid), sheets, result.w, o.parameters, result, clock);
  mpi::recordPointsOff (points.points.size (), result);
  stats.w_triangles = result.surface.triangles.size ();
  stats.w_dangling_edges = result.surface.dangling_edges.size ();
  stats.w_isolated_vertices = result.surface.isolated_vertices.size ();
  stats.total_seconds = 0;
  for (const StageTiming& t : stats.timings)
    stats.total_seconds += t.seconds;
  writeOutputs (o, points, result);
  if (o.stats)
  {
    apps::printSummary (std::cout, stats);
    peaks[0] = peakMegabytes (); // with the mesh written
    std::cout << "tiles:         " << ranks << ", ghosts " << ghosts << " (" << 100.0 * ghosts / points_kept
              << "% of the points), " << completion.rounds << " rounds, " << bytes << " bytes of points sent, "
              << questions << " tetrahedra asked about (" << by_nearest << " answered by the nearest point)\n"
              << "retraction:    " << retraction_rounds << " rounds, " << removals << " removals sent\n"
              << "peak memory:   ";
    for (std::size_t r = 0; r < peaks.size (); ++r)
      std::cout << (r ? ", " : "") << static_cast<long> (peaks[r]) << " MB";
    std::cout << " (per rank)\n";
  }
  if (!o.quiet)
    std::cerr << "pcl_wrap_mpi: wrote " << o.output << ": " << result.surface.triangles.size () << " triangles from "
              << ranks << " tiles\n";
  return 0;
}

} // namespace

int
main (int argc, char** argv)
{
  MPI_Init (&argc, &argv);
  int rank = 0;
  MPI_Comm_rank (MPI_COMM_WORLD, &rank);
  Options o;
  int code = 0;
  if (parseOptions (argc, argv, o, rank, code))
    try
    {
      code = run (o, MPI_COMM_WORLD);
    }
    catch (const std::exception& e)
    {
      // Every rank reads the same input and fails alike; a failure of one rank alone ends all.
      std::cerr << "pcl_wrap_mpi: " << e.what () << '\n';
      MPI_Abort (MPI_COMM_WORLD, 1);
    }
  MPI_Finalize ();
  return code;
}
