// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap_mpi under a real mpirun, 1 to 4 ranks (and 8 on a cloud of 6 points), against the
// single process: X and W identical, simplex by simplex, triangles with their orientation; the
// default surface identical, byte for byte as written.
#include "support/degenerate_samples.h"
#include "support/samplers.h"

#include "point_file.h"
#include "wrap_report.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/statistics_json.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{

using namespace pcl_wrap;
namespace fs = std::filesystem;

fs::path
scratch ()
{
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path () / ("pcl_wrap_test_mpi_" + std::to_string (::getpid ()));
    fs::create_directories (d);
    return d;
  }();
  return dir;
}

/** Writes x y z [w] lines (NaN as "nan"). */
fs::path
writeCloud (const std::string& name, const std::vector<Point3>& points, const std::vector<double>& weights = {})
{
  const fs::path path = scratch () / (name + ".xyz");
  std::ofstream out (path);
  out.precision (17);
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    out << points[i][0] << ' ' << points[i][1] << ' ' << points[i][2];
    if (!weights.empty ())
      out << ' ' << weights[i];
    out << '\n';
  }
  return path;
}

/** \a count weights drawn uniformly from [0, \a largest), seeded by \a seed. */
std::vector<double>
randomWeights (std::size_t count, double largest, unsigned seed)
{
  std::mt19937 random (seed);
  std::uniform_real_distribution<double> weight (0.0, largest);
  std::vector<double> weights (count);
  for (double& w : weights)
    w = weight (random);
  return weights;
}

std::string
readFile (const fs::path& path)
{
  std::ifstream in (path);
  std::stringstream s;
  s << in.rdbuf ();
  return s.str ();
}

/** The part of a --complex JSON that holds the input's fate, X and W. */
std::string
xAndW (const std::string& json)
{
  const std::size_t end = json.find (",\"surface\"");
  return end == std::string::npos ? "(no complex: " + json.substr (0, 200) + ")" : json.substr (0, end);
}

/** Runs pcl_wrap_mpi on \a ranks ranks; returns its exit status. */
int
runMpi (int ranks, const std::string& arguments, const fs::path& log)
{
  // mpirun refuses root unless told; the containers the tests run in often are root.
  ::setenv ("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv ("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  // Each test process has an Open MPI session directory of its own. The default one is shared by
  // every mpirun of a user on a host, and each mpirun removes it when it ends, under any other
  // mpirun that ctest -j runs beside it.
  ::setenv ("OMPI_MCA_orte_tmpdir_base", scratch ().c_str (), 1);
  const std::string command = std::string (PCL_WRAP_MPIRUN) + " --oversubscribe -np " + std::to_string (ranks) + " " +
                              PCL_WRAP_MPI_CLI + " " + arguments + " > " + log.string () + " 2>&1";
  const int status = std::system (command.c_str ());
  return WIFEXITED (status) ? WEXITSTATUS (status) : -1;
}

/** X and W of one process on \a cloud, as pcl_wrap --complex writes them. */
std::string
singleProcess (const fs::path& cloud, bool weights_column)
{
  const apps::PointFile file = apps::readPointFile (cloud.string (), "", weights_column);
  WrapParameters parameters;
  parameters.output = Output::raw;
  parameters.keep_complex = true;
  const WrapResult result = computeWrap (file.points, file.weights, parameters);
  std::ostringstream json;
  apps::writeComplexJson (json, result, file.points.size ());
  return xAndW (json.str ());
}

void
expectIdentical (const fs::path& cloud, std::vector<int> rank_counts = {1, 2, 3, 4}, bool weights_column = false)
{
  const std::string expected = singleProcess (cloud, weights_column);
  for (int ranks : rank_counts)
  {
    const fs::path json = scratch () / (cloud.stem ().string () + "_" + std::to_string (ranks) + ".json");
    const fs::path log = scratch () / "mpi.log";
    const std::string arguments = cloud.string () + " " + (scratch () / "out.ply").string () +
                                  " --raw --quiet --complex " + json.string () +
                                  (weights_column ? " --weights-column" : "");
    ASSERT_EQ (runMpi (ranks, arguments, log), 0) << readFile (log);
    EXPECT_TRUE (xAndW (readFile (json)) == expected) << cloud << " on " << ranks << " ranks: X or W differ";
  }
}

TEST (Mpi, RandomPointsInACube)
{
  expectIdentical (writeCloud ("cube", test::cubeSample (3000, 1)));
}

TEST (Mpi, NoisySphere)
{
  expectIdentical (writeCloud ("sphere", test::sphereSample (6000, 2, 3e-3)));
}

TEST (Mpi, ThinShellIsAnsweredByTheNearestPoint)
{
  // The orthosphere of four points of a thin shell is nearly the shell: it meets every box of the
  // other tile's k-d tree though it holds none of its points, and the nearest point answers.
  const fs::path cloud = writeCloud ("shell", test::sphereSample (8000, 6, 1e-4));
  expectIdentical (cloud, {2, 3});
  const fs::path log = scratch () / "shell.log";
  ASSERT_EQ (runMpi (2, cloud.string () + " " + (scratch () / "out.ply").string () + " --raw --stats", log), 0);
  std::smatch answered;
  const std::string stats = readFile (log);
  ASSERT_TRUE (std::regex_search (stats, answered, std::regex ("\\(([0-9]+) answered by the nearest point\\)")))
      << stats;
  EXPECT_GT (std::stoul (answered[1]), 100u) << stats;
}

TEST (Mpi, TorusWithItsTunnel)
{
  expectIdentical (writeCloud ("torus", test::torusSample (5000, 3)));
}

TEST (Mpi, TerrainOfSheets)
{
  expectIdentical (writeCloud ("terrain", test::terrainSample (3000, 4)));
}

TEST (Mpi, WeightedPointsSomeHidden)
{
  const std::vector<Point3> points = test::cubeSample (2000, 5);
  expectIdentical (writeCloud ("weighted", points, randomWeights (points.size (), 4e-3, 5)), {1, 2, 3, 4}, true);
}

TEST (Mpi, CosphericalGrid)
{
  expectIdentical (writeCloud ("grid", test::gridSample (11, 11, 11)));
}

TEST (Mpi, TileBorderThroughAGridPlane)
{
  // The first cut halves the longest side, z, at the median: through the 400 grid points at z = 0.
  std::vector<Point3> points;
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j)
      points.push_back ({double (i), double (j), 0.0});
  for (const Point3& p : test::cubeSample (1200, 6))
    points.push_back ({19 * p[0], 19 * p[1], p[2] < 0.5 ? 21 * p[2] - 11 : 21 * p[2] - 10});
  expectIdentical (writeCloud ("plane", points));
}

TEST (Mpi, DuplicatesAndNonFinitePoints)
{
  std::vector<Point3> points = test::cubeSample (1000, 7);
  for (int i = 0; i < 40; ++i)
    points.push_back (points[7 * i]);
  points.push_back ({std::nan (""), 0, 0});
  expectIdentical (writeCloud ("duplicates", points));
}

TEST (Mpi, FarApartClustersAndTilesOfOnePoint)
{
  std::vector<Point3> points = test::cubeSample (800, 8);
  for (const Point3& p : test::cubeSample (800, 9))
    points.push_back ({p[0] + 100, p[1], p[2]});
  expectIdentical (writeCloud ("far", points));
  // Six points on eight ranks: tiles of one point, whose every tetrahedron reaches the others,
  // and two tiles with none.
  expectIdentical (writeCloud ("six", test::cubeSample (6, 10)), {4, 8});
}

TEST (Mpi, FolderOfTileFilesIsTheirConcatenation)
{
  // Three files of a noisy sphere, read by different ranks; one process reads them as one file.
  std::vector<Point3> points = test::sphereSample (4000, 13, 3e-3);
  points[1234] = {std::nan (""), 0, 0};
  points[3000] = points[17]; // a duplicate across files
  const fs::path folder = scratch () / "tiles";
  fs::create_directories (folder);
  const std::size_t cut[] = {0, 1500, 2600, points.size ()};
  for (int f = 0; f < 3; ++f)
  {
    const std::vector<Point3> part (points.begin () + cut[f], points.begin () + cut[f + 1]);
    fs::rename (writeCloud ("part", part), folder / ("part" + std::to_string (f) + ".xyz"));
  }
  const std::string expected = singleProcess (writeCloud ("whole", points), false);
  for (int ranks : {1, 2, 3, 4})
  {
    const fs::path json = scratch () / "folder.json", log = scratch () / "folder.log";
    ASSERT_EQ (runMpi (ranks,
                       folder.string () + " " + (scratch () / "folder.ply").string () + " --raw --quiet --complex " +
                           json.string (),
                       log),
               0)
        << readFile (log);
    EXPECT_TRUE (xAndW (readFile (json)) == expected) << "a folder of three files on " << ranks << " ranks";
  }
}

TEST (Mpi, RealScan)
{
  expectIdentical (fs::path (PCL_WRAP_DATA_DIR) / "bunny00.off", {2, 4});
}

TEST (Mpi, MissingOrMalformedInputIsAClearError)
{
  const fs::path log = scratch () / "missing.log", out = scratch () / "m.ply";
  EXPECT_EQ (runMpi (2, (scratch () / "nothing_here.xyz").string () + " " + out.string () + " --raw", log), 1);
  EXPECT_NE (readFile (log).find ("no such file or folder"), std::string::npos) << readFile (log);
  const fs::path bad = scratch () / "bad.xyz";
  std::ofstream (bad) << "1 2 3\n4 5\n";
  EXPECT_EQ (runMpi (2, bad.string () + " " + out.string () + " --raw", log), 1);
  EXPECT_NE (readFile (log).find ("line 2"), std::string::npos) << readFile (log);
  EXPECT_FALSE (fs::exists (out));
}

TEST (Mpi, OutputOverTheInputIsRefused)
{
  const fs::path cloud = writeCloud ("over", test::cubeSample (50, 14)), log = scratch () / "over.log";
  const std::string before = readFile (cloud);
  EXPECT_EQ (runMpi (2,
                     cloud.string () + " " + (scratch () / "o.ply").string () + " --raw --stats-json " +
                         cloud.string (),
                     log),
             2);
  EXPECT_EQ (readFile (cloud), before);
}

/** pcl_wrap's output on \a cloud (the default surface unless \a parameters say otherwise), as it
  * writes it to \a mesh. */
void
writeSingleProcessSurface (const fs::path& cloud, const fs::path& mesh, bool weights_column,
                           WrapParameters parameters = {})
{
  const apps::PointFile file = apps::readPointFile (cloud.string (), "", weights_column);
  parameters.viewpoint = file.viewpoint;
  apps::writeSurfaceMesh (mesh.string (), file, computeWrap (file.points, file.weights, parameters));
}

/** The default surface (or what \a options ask for, as \a parameters do) on \a ranks ranks is the
  * single process's, byte for byte. */
void
expectIdenticalSurface (const fs::path& cloud, std::vector<int> rank_counts = {1, 2, 3, 4}, bool weights_column = false,
                        const std::string& options = "", const WrapParameters& parameters = {})
{
  const fs::path expected = scratch () / (cloud.stem ().string () + "_single.ply");
  writeSingleProcessSurface (cloud, expected, weights_column, parameters);
  const std::string single = readFile (expected);
  ASSERT_GT (single.size (), 100u);
  for (int ranks : rank_counts)
  {
    const fs::path mesh = scratch () / (cloud.stem ().string () + "_" + std::to_string (ranks) + ".ply");
    const fs::path log = scratch () / "surface.log";
    ASSERT_EQ (runMpi (ranks,
                       cloud.string () + " " + mesh.string () + " --quiet" +
                           (weights_column ? " --weights-column" : "") + options,
                       log),
               0)
        << readFile (log);
    EXPECT_TRUE (readFile (mesh) == single)
        << cloud << " on " << ranks << " ranks" << options << ": the output differs";
  }
}

TEST (Mpi, DefaultSurfaceIsTheSingleProcesssOnClosedShapes)
{
  expectIdenticalSurface (writeCloud ("sphere_surface", test::sphereSample (6000, 2, 3e-3)));
  expectIdenticalSurface (writeCloud ("torus_surface", test::torusSample (5000, 3)), {3});
  // Two objects apart: the surface stage keeps them apart, whichever tiles they fall in.
  std::vector<Point3> points = test::sphereSample (3000, 15, 1e-3);
  for (const Point3& p : test::torusSample (3000, 16))
    points.push_back ({p[0] + 3, p[1], p[2]});
  expectIdenticalSurface (writeCloud ("apart_surface", points), {2, 4});
}

TEST (Mpi, PointsSpanningNoVolumeAreWrappedAsOneProcessWrapsThem)
{
  // A plane, a line, three points and one (twice) span no volume: Del S has no tetrahedron, and rank 0 wraps
  // them alone. Two parallel planes do, though each tile may hold one plane alone. The output is
  // the single process's in every case.
  std::vector<Point3> flat, line, planes;
  for (const Point3& p : test::cubeSample (200, 11))
  {
    flat.push_back ({p[0], p[1], 0.0});
    line.push_back ({p[0], 2 * p[0], 4 * p[0]}); // exactly collinear
    planes.push_back ({p[0], p[1], p[2] < 0.5 ? 0.0 : 1.0});
  }
  const std::vector<Point3> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, one = {{1, 2, 3}, {1, 2, 3}};
  for (const auto& [name, points] : {std::pair{"flat", flat}, std::pair{"line", line}, std::pair{"planes", planes},
                                     std::pair{"three", three}, std::pair{"one", one}})
  {
    const fs::path cloud = writeCloud (name, points);
    expectIdentical (cloud, {1, 2, 3});
    expectIdenticalSurface (cloud, {2, 3});
  }
  const fs::path log = scratch () / "flat.log";
  ASSERT_EQ (runMpi (2, writeCloud ("flat", flat).string () + " " + (scratch () / "f.ply").string () + " --stats", log),
             0)
      << readFile (log);
  EXPECT_NE (readFile (log).find ("rank 0 wrapped them alone"), std::string::npos) << readFile (log);
}

/** The "points" of a --stats-json and the lists after it (hidden, apart, off_surface). */
std::string
pointsOfStatistics (const std::string& json)
{
  return json.substr (0, json.find (",\"triangulation_dimension\""));
}

TEST (Mpi, PointsLeftOffAreTheSingleProcesss)
{
  // A volume (most points inside), a duplicate and a far outlier.
  std::vector<Point3> points = test::cubeSample (4000, 21);
  points.push_back (points[7]);
  points.push_back ({30.0, 0.0, 0.0});
  const fs::path cloud = writeCloud ("points_off", points), json = scratch () / "points_off.json",
                 log = scratch () / "points_off.log";
  const apps::PointFile file = apps::readPointFile (cloud.string (), "", false);
  for (const bool raw : {false, true})
  {
    WrapParameters parameters;
    parameters.output = raw ? Output::raw : Output::surface;
    const WrapResult single = computeWrap (file.points, file.weights, parameters);
    ASSERT_GT (single.off_surface.size (), 1000u);
    EXPECT_EQ (single.apart, raw ? std::vector<PointIndex>{} : std::vector<PointIndex>{4001});
    for (int ranks : {1, 3})
    {
      ASSERT_EQ (runMpi (ranks,
                         cloud.string () + " " + (scratch () / "o.ply").string () + (raw ? " --raw" : "") +
                             " --quiet --stats-json " + json.string (),
                         log),
                 0)
          << readFile (log);
      EXPECT_EQ (pointsOfStatistics (readFile (json)), pointsOfStatistics (statisticsJson (single)))
          << ranks << " ranks" << (raw ? ", raw" : "");
    }
  }
}

/** The "spacing" of a --stats-json: its value as written. */
std::string
spacingOfStatistics (const std::string& json)
{
  const std::size_t at = json.find ("\"spacing\":");
  return at == std::string::npos ? "(none)" : json.substr (at, json.find (',', at) - at);
}

TEST (Mpi, ComplexAndSpacingAreTheSingleProcesss)
{
  // The whole --complex file (X with its classes' counts, W, the output, the wrap filtration
  // and its sinks) and the median spacing, for the raw W and the default surface.
  const std::vector<Point3> weighted = test::cubeSample (1500, 23);
  const std::vector<std::pair<fs::path, bool>> clouds = {
      {writeCloud ("complex_sphere", test::sphereSample (3000, 22, 3e-3)), false},
      {writeCloud ("complex_weighted", weighted, randomWeights (weighted.size (), 4e-3, 23)), true}};
  for (const auto& [cloud, weights_column] : clouds)
  {
    const apps::PointFile file = apps::readPointFile (cloud.string (), "", weights_column);
    for (const bool raw : {true, false})
    {
      WrapParameters parameters;
      parameters.output = raw ? Output::raw : Output::surface;
      parameters.keep_complex = parameters.filtration = true;
      const WrapResult single = computeWrap (file.points, file.weights, parameters);
      ASSERT_FALSE (single.filtration.empty ());
      ASSERT_GT (single.statistics.spacing, 0.0);
      std::ostringstream expected;
      apps::writeComplexJson (expected, single, file.points.size ());
      for (int ranks : {1, 2, 3})
      {
        const fs::path json = scratch () / "complex.json", stats = scratch () / "complex_stats.json",
                       log = scratch () / "complex.log";
        ASSERT_EQ (runMpi (ranks,
                           cloud.string () + " " + (scratch () / "c.ply").string () + (raw ? " --raw" : "") +
                               (weights_column ? " --weights-column" : "") + " --quiet --complex " + json.string () +
                               " --stats-json " + stats.string (),
                           log),
                   0)
            << readFile (log);
        EXPECT_TRUE (readFile (json) == expected.str ())
            << cloud << " on " << ranks << " ranks" << (raw ? ", raw" : "") << ": the complex differs";
        EXPECT_EQ (spacingOfStatistics (readFile (stats)), spacingOfStatistics (statisticsJson (single)))
            << cloud << " on " << ranks << " ranks";
      }
    }
  }
}

TEST (Mpi, DefaultSurfaceIsTheSingleProcesssOnNoiseOfASpacing)
{
  // Noise of a spacing (40,000 points on the unit sphere are about 0.009 apart): the repair
  // moves thousands of tetrahedra, weakest first, ties broken by their numbering.
  const std::vector<Point3> points = test::noisySphereSample (40000, 17, 0.009);
  expectIdenticalSurface (writeCloud ("noisy_surface", points), {2, 3});
}

TEST (Mpi, DefaultSurfaceIsTheSingleProcesssOnASingleLayerAndOddInput)
{
  expectIdenticalSurface (writeCloud ("terrain_surface", test::terrainSample (3000, 4)), {1, 3});
  // Noise of about a spacing across the layer: a sample of the points, the same in every
  // process, tells it from a solid.
  const std::vector<Point3> noisy = test::noisyTerrainSample (6000, 21, 0.5);
  const WrapStatistics judged = computeWrap (noisy).statistics;
  ASSERT_TRUE (judged.single_layer && std::any_of (judged.timings.begin (), judged.timings.end (),
                                                   [] (const StageTiming& t) { return t.stage == "layer sample"; }));
  expectIdenticalSurface (writeCloud ("noisy_terrain_surface", noisy), {2});
  std::vector<Point3> points = test::sphereSample (2000, 18, 1e-3);
  for (int i = 0; i < 40; ++i)
    points.push_back (points[7 * i]);
  points.push_back ({std::nan (""), 0, 0});
  expectIdenticalSurface (writeCloud ("duplicates_surface", points), {2});
  const std::vector<Point3> weighted = test::sphereSample (2000, 20, 1e-3);
  expectIdenticalSurface (writeCloud ("weighted_surface", weighted, randomWeights (weighted.size (), 1e-3, 19)), {2},
                          true);
}

TEST (Mpi, ThresholdsAreTheSingleProcesss)
{
  // Rank 0 deletes the sinks as one process does, for the raw W and under the default surface;
  // each threshold here changes the output, so an ignored one would show.
  const fs::path bunny = fs::path (PCL_WRAP_DATA_DIR) / "bunny00.off";
  const auto changes = [&] (const fs::path& cloud, WrapParameters without, const WrapParameters& with) {
    without.output = with.output;
    const fs::path a = scratch () / "without.ply", b = scratch () / "with.ply";
    writeSingleProcessSurface (cloud, a, false, without);
    writeSingleProcessSurface (cloud, b, false, with);
    return readFile (a) != readFile (b);
  };
  WrapParameters global;
  global.output = Output::raw;
  global.threshold = Threshold::relativeRadius (4);
  global.deletion = SinkDeletion::global;
  EXPECT_TRUE (changes (bunny, {}, global));
  expectIdenticalSurface (bunny, {2, 3}, false, " --raw --radius-rel 4 --mode global", global);

  WrapParameters front;
  front.threshold = Threshold::relativeRadius (4);
  EXPECT_TRUE (changes (bunny, {}, front));
  expectIdenticalSurface (bunny, {2}, false, " --radius-rel 4", front);

  const fs::path torus = writeCloud ("torus_sinks", test::torusSample (3000, 21));
  WrapParameters largest;
  largest.output = Output::raw;
  largest.threshold = Threshold::largest (3);
  EXPECT_TRUE (changes (torus, {}, largest));
  expectIdenticalSurface (torus, {2}, false, " --raw --sinks 3", largest);
}

TEST (Mpi, ThresholdWithComplexOrTwoThresholdsIsAUsageError)
{
  const fs::path cloud = writeCloud ("usage", test::cubeSample (50, 12)), log = scratch () / "usage.log";
  EXPECT_EQ (runMpi (2, cloud.string () + " u.ply --sinks 2 --complex u.json", log), 2);
  EXPECT_NE (readFile (log).find ("--complex"), std::string::npos) << readFile (log);
  EXPECT_EQ (runMpi (2, cloud.string () + " u.ply --sinks 2 --delta 1", log), 2);
  EXPECT_EQ (runMpi (2, cloud.string () + " u.ply --sinks 0", log), 2);
}

} // namespace
