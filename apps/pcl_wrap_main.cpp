// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap INPUT OUTPUT [options]: wraps the points of INPUT and writes the surface to OUTPUT.
#include "mesh_file.h"
#include "point_file.h"
#include "threshold_option.h"
#include "wrap_report.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/statistics_json.h>
#include <pcl_wrap/version.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <system_error>
#include <unistd.h>
#include <vector>

namespace
{

using namespace pcl_wrap;

/** Do the paths name the same file (the same path, or the same existing file by another)? */
bool
sameFile (const std::string& a, const std::string& b)
{
  std::error_code error;
  return a == b || std::filesystem::equivalent (a, b, error);
}

void
printUsage (std::ostream& out)
{
  const WrapParameters defaults;
  out << "usage: pcl_wrap INPUT OUTPUT [options]\n\n"
         "Wraps the points of INPUT (.pcd .ply .xyz .txt .off .obj) in Edelsbrunner's Wrap surface and\n"
         "writes it to OUTPUT (.ply .obj .vtk .off .stl). The output's vertices are the input points in input\n"
         "order (.stl has no shared vertices: each triangle carries its corners),\n"
         "without the points skipped for a non-finite coordinate or weight. Colours, normals and\n"
         "other fields of the input points are kept on the vertices where the format has them\n"
         "(.ply: all; .vtk: all; .obj and .off: colours and normals; .stl: none).\n\n"
         "options:\n"
         "  --complex FILE.json   write the complex: X by dimension, the paper's W = Bd X, the output\n"
         "                        surface, hidden points, class counts, the deletion counts and the\n"
         "                        wrap filtration (each simplex of X with the sink size at which it\n"
         "                        leaves; all sink sizes)\n"
         "  --stats               print a summary\n"
         "  --stats-json FILE     write the statistics, with timings per stage, as JSON\n"
         "  --delta D             wrap tighter: delete sinks (empty spheres) of squared radius > D\n"
         "  --radius R            the same with D = R^2\n"
         "  --radius-rel K        the same with R = K x the median nearest-neighbour distance\n"
         "  --mode front|global   front (default): only sinks whose basin reaches the surface, so no\n"
         "                        cavity is carved; global: every sink above the threshold\n"
         "  --sinks J             delete the J largest sinks (a global deletion)\n"
         "  --region sphere:x,y,z,r | box:x0,y0,z0,x1,y1,z1\n"
         "                        local modification: front deletion with the threshold above starts\n"
         "                        only from the surface inside this region\n"
         "  --raw                 write the paper's W = Bd X as it is (pinch edges and vertices,\n"
         "                        sheets) instead of the default surface, an oriented 2-manifold\n"
         "                        through the points: closed, or for a single layer (a terrain, a\n"
         "                        scan seen from one side) one open sheet\n"
         "  --closed              a single layer too as a closed surface: a two-sided shell, its\n"
         "                        points copied per side (copies follow the input)\n"
         "  --viewpoint X,Y,Z     where the sensor was: a single layer's sheet faces it (default:\n"
         "                        a .pcd file's VIEWPOINT when the cloud is organised or it is set,\n"
         "                        else up, +z)\n"
         "  --manifold            with --raw: split W where it touches itself, so that the output\n"
         "                        is a closed 2-manifold: copies of the split points follow the input\n"
         "  --weight-field NAME   weights (squared radii) from this field of a .pcd or .ply input\n"
         "  --weights-column      weights from the 4th column of a .xyz/.txt input (x y z w ...);\n"
         "                        without it, further columns are kept as vertex fields\n"
         "  --weight-scale S      multiply every weight by S (default "
      << defaults.weight_scale
      << ")\n"
         "  --threads N           worker threads, 0 = all cores (default "
      << defaults.num_threads
      << ")\n"
         "  --progress            progress on stderr even when it is not a terminal\n"
         "  --quiet               no progress and no warnings\n"
         "  --version             the version\n"
         "  -h, --help            this text\n";
}

struct Options
{
  std::string input, output, complex_json, stats_json, weight_field;
  bool stats = false, quiet = false, progress = false, raw = false, closed = false, weights_column = false;
  int thresholds = 0; // --delta, --radius, --radius-rel and --sinks given: at most one
  WrapParameters parameters;
};

/** "sphere:x,y,z,r" or "box:x0,y0,z0,x1,y1,z1"; false when it is neither. */
bool
parseRegion (const std::string& spec, Region& region)
{
  const std::size_t colon = spec.find (':');
  const std::string shape = spec.substr (0, colon);
  const std::size_t count = shape == "sphere" ? 4 : shape == "box" ? 6 : 0;
  if (count == 0 || colon == std::string::npos)
    return false;
  std::array<double, 6> v{};
  const char* p = spec.c_str () + colon + 1;
  for (std::size_t i = 0; i < count; ++i)
  {
    char* end = nullptr;
    v[i] = std::strtod (p, &end);
    if (end == p || !std::isfinite (v[i]) || *end != (i + 1 < count ? ',' : '\0'))
      return false;
    p = end + (i + 1 < count);
  }
  region = count == 4 ? Region::sphere (v[0], v[1], v[2], v[3]) : Region::box (v[0], v[1], v[2], v[3], v[4], v[5]);
  return count == 4 ? v[3] >= 0 : v[0] <= v[3] && v[1] <= v[4] && v[2] <= v[5];
}

/** Parses the command line; exits with 2 (usage) or 0 (--help). */
Options
parseOptions (int argc, char** argv)
{
  Options o;
  std::vector<std::string> positional;
  const auto usageError = [] (const std::string& message) {
    std::cerr << "pcl_wrap: " << message << " (see pcl_wrap --help)\n";
    std::exit (2);
  };
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&] () -> std::string {
      if (i + 1 >= argc)
        usageError (arg + " needs a value");
      return argv[++i];
    };
    if (arg == "-h" || arg == "--help")
    {
      printUsage (std::cout);
      std::exit (0);
    }
    else if (arg == "--version")
    {
      std::cout << "pcl_wrap " << PCL_WRAP_VERSION << "\n";
      std::exit (0);
    }
    else if (arg == "--complex")
      o.complex_json = value ();
    else if (arg == "--stats")
      o.stats = true;
    else if (arg == "--stats-json")
      o.stats_json = value ();
    else if (arg == "--quiet")
      o.quiet = true;
    else if (arg == "--progress")
      o.progress = true;
    else if (arg == "--weights-column")
      o.weights_column = true;
    else if (apps::isThresholdOption (arg))
    {
      const std::string error = apps::applyThresholdOption (arg, value (), o.parameters, o.thresholds);
      if (!error.empty ())
        usageError (error);
    }
    else if (arg == "--region")
    {
      if (!parseRegion (value (), o.parameters.region))
        usageError ("--region takes sphere:x,y,z,r (r >= 0) or box:x0,y0,z0,x1,y1,z1 (lowest corner first)");
    }
    else if (arg == "--raw")
      o.raw = true;
    else if (arg == "--closed")
      o.closed = true;
    else if (arg == "--viewpoint")
    {
      const std::string v = value ();
      std::array<double, 3> p{};
      const char* at = v.c_str ();
      for (int k = 0; k < 3; ++k)
      {
        char* end = nullptr;
        p[k] = std::strtod (at, &end);
        if (end == at || !std::isfinite (p[k]) || *end != (k < 2 ? ',' : '\0'))
          usageError ("--viewpoint takes three finite numbers X,Y,Z");
        at = end + 1;
      }
      o.parameters.viewpoint = p;
    }
    else if (arg == "--manifold")
      o.parameters.manifold = true;
    else if (arg == "--weight-field")
      o.weight_field = value ();
    else if (arg == "--weight-scale")
    {
      const std::string v = value ();
      char* end = nullptr;
      const double scale = std::strtod (v.c_str (), &end);
      if (v.empty () || *end != '\0' || !std::isfinite (scale))
        usageError ("--weight-scale takes a finite number");
      o.parameters.weight_scale = scale;
    }
    else if (arg == "--threads")
    {
      const std::string v = value ();
      char* end = nullptr;
      const long n = std::strtol (v.c_str (), &end, 10);
      if (v.empty () || *end != '\0' || n < 0 || n > 4096)
        usageError ("--threads takes a whole number from 0 to 4096");
      o.parameters.num_threads = static_cast<unsigned> (n);
    }
    else if (arg.size () > 1 && arg[0] == '-')
      usageError ("unknown option " + arg);
    else
      positional.push_back (arg);
  }
  if (positional.size () != 2)
    usageError ("expected INPUT and OUTPUT");
  o.parameters.filtration = !o.complex_json.empty ();
  o.parameters.keep_complex = !o.complex_json.empty (); // nothing else reads it
  o.input = positional[0];
  o.output = positional[1];
  if (o.raw && o.closed)
    usageError ("--closed applies to the default surface, not to the raw W (--raw)");
  o.parameters.output = o.raw ? Output::raw : o.closed ? Output::closed : Output::surface;
  if (o.parameters.manifold && o.parameters.output != Output::raw)
    usageError ("--manifold splits the raw W (--raw); the default surface is a 2-manifold already");
  for (const std::string& written : {o.output, o.complex_json, o.stats_json})
    if (!written.empty () && sameFile (written, o.input))
      usageError (written + " is the input: it would be overwritten");
  try
  {
    checkParameters (o.parameters); // e.g. a region without a threshold, before reading the input
  }
  catch (const std::invalid_argument& e)
  {
    usageError (e.what ());
  }
  if (!apps::isMeshFormat (o.output))
    usageError (o.output + ": unknown output format (expected .ply, .obj, .vtk, .off or .stl)");
  if (o.quiet && o.progress)
    usageError ("--quiet and --progress contradict each other");
  return o;
}

/** Progress on stderr: a line per stage; on a terminal the running stage's share in place. */
class ProgressReport
{
public:
  ProgressReport (bool on) : on_ (on), terminal_ (::isatty (STDERR_FILENO)) {}

  void stage (const std::string& name, double seconds)
  {
    if (!on_)
      return;
    std::cerr << (terminal_ ? "\r\033[K" : "") << "  " << std::left << std::setw (16) << name << std::right
              << std::fixed << std::setprecision (3) << seconds << " s\n"
              << std::defaultfloat;
  }

  void within (const std::string& name, double done)
  {
    if (!on_)
      return;
    const int percent = static_cast<int> (100 * done + 0.5);
    if (terminal_)
      std::cerr << "\r\033[K  " << std::left << std::setw (16) << name << std::right << percent << " %" << std::flush;
    else if (percent % 25 == 0 && percent < 100) // a log: a line now and then
      std::cerr << "  " << std::left << std::setw (16) << name << std::right << percent << " %\n";
  }

  explicit operator bool () const { return on_; }

private:
  bool on_, terminal_;
};

} // namespace

int
main (int argc, char** argv)
{
  const Options o = parseOptions (argc, argv);
  ProgressReport progress (!o.quiet && (o.progress || ::isatty (STDERR_FILENO)));
  try
  {
    const apps::PointFile file = apps::readPointFile (o.input, o.weight_field, o.weights_column);
    const std::vector<Point3>& points = file.points;
    const auto finite = [] (const Point3& p) {
      return std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]);
    };
    if (std::none_of (points.begin (), points.end (), finite))
      throw apps::FileError (o.input + ": no point with finite coordinates (" + std::to_string (points.size ()) +
                             " points, none of them finite)");
    if (progress)
    {
      std::cerr << "pcl_wrap: " << points.size () << " points from " << o.input;
      const std::string carried = file.attributes.describe ();
      std::cerr << (carried.empty () ? "" : " with " + carried) << '\n';
    }
    WrapParameters parameters = o.parameters;
    if (!parameters.viewpoint && file.viewpoint)
      parameters.viewpoint = *file.viewpoint;
    const WrapResult result = computeWrap (
        points, file.weights, parameters,
        [&] (const std::string& stage, double seconds) { progress.stage (stage, seconds); },
        progress ? ProgressObserver ([&] (const std::string& stage, double done) { progress.within (stage, done); })
                 : ProgressObserver ());
    if (!o.quiet && !result.skipped.empty ())
      std::cerr << "pcl_wrap: " << result.skipped.size () << (result.skipped.size () == 1 ? " point" : " points")
                << " skipped for a non-finite coordinate or weight, and left out of the output\n";

    const std::size_t vertices = apps::writeSurfaceMesh (o.output, file, result);
    if (!o.complex_json.empty ())
      apps::writeAtomically (o.complex_json,
                             [&] (std::ostream& out) { apps::writeComplexJson (out, result, points.size ()); });
    if (!o.stats_json.empty ())
      apps::writeAtomically (o.stats_json, [&] (std::ostream& out) { out << statisticsJson (result) << '\n'; });
    if (progress)
    {
      const std::string kept = apps::attributesKeptBy (o.output, file.attributes);
      std::cerr << "pcl_wrap: wrote " << o.output << ": " << result.surface.triangles.size () << " triangles, "
                << vertices << " vertices" << (kept.empty () ? "" : " with " + kept) << '\n';
    }
    if (o.stats)
      apps::printSummary (std::cout, result.statistics);
  }
  catch (const std::exception& e)
  {
    std::cerr << "pcl_wrap: " << e.what () << '\n';
    return 1;
  }
  return 0;
}
