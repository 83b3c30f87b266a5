// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The pcl_wrap command-line tool, run as a user runs it: every input and output format, the
// JSON files, and one clear error line with no output for every malformed input.
#include "point_file.h"
#include "support/pcl_mesh.h"
#include "support/samplers.h"
#include "support/topology.h"

#include <pcl_wrap/compute_wrap.h>

#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/io/obj_io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_lib_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

namespace pcl_wrap::test
{
namespace
{

const std::string DIR = ::testing::TempDir () + "pcl_wrap_cli/";

struct CliRun
{
  int status;
  std::string err;
};

CliRun
runCli (const std::string& arguments)
{
  // ctest runs the tests of this file in parallel processes: one stderr file per test.
  const std::string err_file = DIR + ::testing::UnitTest::GetInstance ()->current_test_info ()->name () + ".err";
  const int raw = std::system ((std::string (PCL_WRAP_CLI) + " " + arguments + " > /dev/null 2> " + err_file).c_str ());
  std::ifstream in (err_file);
  std::stringstream err;
  err << in.rdbuf ();
  return {WIFEXITED (raw) ? WEXITSTATUS (raw) : -1, err.str ()};
}

bool
exists (const std::string& path)
{
  struct stat s;
  return ::stat (path.c_str (), &s) == 0;
}

void
writeText (const std::string& path, const std::string& text)
{
  std::ofstream (path) << text;
}

/** \a points as the lines "x y z" of a .xyz file, to the last bit. */
std::string
xyzText (const std::vector<Point3>& points)
{
  std::ostringstream xyz;
  xyz.precision (17);
  for (const auto& p : points)
    xyz << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  return xyz.str ();
}

class Cli : public ::testing::Test
{
protected:
  static void SetUpTestSuite ()
  {
    ASSERT_EQ (std::system (("mkdir -p " + DIR).c_str ()), 0);
  }
};

TEST_F (Cli, EveryInputFormatGivesTheSameSurfaceInEveryOutputFormat)
{
  // Float coordinates, so that PCD and PLY (float fields) hold exactly the same points.
  std::vector<Point3> points;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const auto& p : sphereSample (500, 4, 1e-3))
  {
    cloud.push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
    points.push_back ({double (float (p[0])), double (float (p[1])), double (float (p[2]))});
  }
  const std::size_t triangles = computeWrap (points).surface.triangles.size ();

  std::ostringstream xyz, off, obj;
  xyz.precision (17), off.precision (17), obj.precision (17);
  xyz << "# a comment\n\n";
  off << "OFF\n" << points.size () << " 0 0\n";
  for (const auto& p : points)
  {
    xyz << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    off << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  writeText (DIR + "in.xyz", xyz.str ());
  writeText (DIR + "in.off", off.str ());
  writeText (DIR + "in.obj", obj.str () + "f 1 2 3\n");
  ASSERT_EQ (pcl::io::savePCDFileBinary (DIR + "in.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePLYFileBinary (DIR + "in.ply", cloud), 0);

  for (const std::string input : {"in.xyz", "in.off", "in.obj", "in.pcd", "in.ply"})
    for (const std::string output : {"out.ply", "out.obj", "out.vtk", "out.off", "out.stl"})
    {
      SCOPED_TRACE (input + " -> " + output);
      std::remove ((DIR + output).c_str ());
      const CliRun run = runCli (DIR + input + " " + DIR + output + " --quiet");
      ASSERT_EQ (run.status, 0) << run.err;
      if (output == "out.off")
      {
        // Its header counts the vertices, the input points, and the triangles; its vertices are
        // the points as a reader of point files sees them.
        std::ifstream in (DIR + output);
        std::string magic, comment;
        std::size_t vertices = 0, faces = 0;
        in >> magic;
        std::getline (in, comment);
        std::getline (in, comment);
        in >> vertices >> faces;
        EXPECT_EQ (magic, "OFF");
        EXPECT_EQ (vertices, points.size ());
        EXPECT_EQ (faces, triangles);
        EXPECT_EQ (apps::readPoints (DIR + output), points);
        continue;
      }
      pcl::PolygonMesh mesh;
      if (output == "out.stl")
      {
        ASSERT_GT (pcl::io::loadPolygonFileSTL (DIR + output, mesh), 0);
        EXPECT_EQ (mesh.polygons.size (), triangles);
        continue;
      }
      if (output == "out.ply")
        ASSERT_GE (pcl::io::loadPLYFile (DIR + output, mesh), 0);
      else if (output == "out.obj")
        ASSERT_GE (pcl::io::loadOBJFile (DIR + output, mesh), 0);
      else
        ASSERT_GT (pcl::io::loadPolygonFileVTK (DIR + output, mesh), 0);
      EXPECT_EQ (mesh.polygons.size (), triangles);
      EXPECT_EQ (std::size_t (mesh.cloud.width) * mesh.cloud.height, points.size ());
    }
}

TEST_F (Cli, WritesComplexAndStatisticsJson)
{
  // A last data line, index 300, to skip.
  writeText (DIR + "torus.xyz", xyzText (torusSample (300, 2)) + "nan 0 0\n");
  const CliRun run = runCli (DIR + "torus.xyz " + DIR + "torus.ply --complex " + DIR + "torus.json --stats-json " +
                          DIR + "torus_stats.json --stats");
  ASSERT_EQ (run.status, 0) << run.err;
  // Checked with Python's JSON parser: valid, the promised keys, sorted simplices, sane counts.
  const std::string check = R"PY(
import json, sys
c = json.load(open(sys.argv[1])); s = json.load(open(sys.argv[2]))
assert c["n"] == 301 and c["skipped"] == [300] and c["hidden"] == []
for k in "0123":
    assert all(x == sorted(x) and len(x) == int(k) + 1 for x in c["X"][k]) and c["X"][k] == sorted(c["X"][k])
assert len(c["X"]["0"]) == 300 and len(c["surface"]["triangles"]) == s["w"]["triangles"] > 0
assert c["W"]["triangles"] and c["W"]["triangles"] != c["surface"]["triangles"]  # the torus's W seals its tunnel
tets = s["simplices"]["3"]
assert sum(c["class_counts"]["3"].values()) == tets["centered"] + tets["confident"] + tets["equivocal"]
chi = sum((-1) ** int(k) * len(c["X"][k]) for k in "0123")
assert chi == 1, chi
t = s["timings"]; assert abs(sum(v for k, v in t.items() if k != "total") - t["total"]) < 1e-6
assert set(t) >= {"triangulation", "classification", "collapse", "filtration", "total"}
f = c["filtration"]; sizes = f["sink_sizes"]
assert sizes == sorted(sizes, reverse=True) and len(sizes) == s["deletion"]["sinks"] > 0
for k in "0123":
    assert len(f[k]) == len(c["X"][k])  # no deletion asked: X is the basic X
    assert all(x[-1] is None or x[-1] in sizes for x in f[k])
assert any(x[-1] is not None for x in f["3"]) and c["deletion"]["deleted"] == 0
)PY";
  writeText (DIR + "check.py", check);
  EXPECT_EQ (std::system (("python3 " + DIR + "check.py " + DIR + "torus.json " + DIR + "torus_stats.json").c_str ()),
             0);
}

TEST_F (Cli, ComplexJsonHasThePapersWWhateverTheOutput)
{
  writeText (DIR + "w_torus.xyz", xyzText (torusSample (400, 3)));
  for (const std::string output : {"default", "raw"})
    ASSERT_EQ (runCli (DIR + "w_torus.xyz " + DIR + "w_torus.ply --complex " + DIR + output + ".json" +
                       (output == "raw" ? " --raw" : ""))
                   .status,
               0);
  // The raw output is W itself; the default surface differs from it (W seals the tunnel).
  const std::string check = R"PY(
import json, sys
d = json.load(open(sys.argv[1])); r = json.load(open(sys.argv[2]))
assert d["W"] == r["W"] and d["X"] == r["X"]
assert r["surface"]["triangles"] == r["W"]["triangles"] and r["surface"]["copies"] == []
assert d["surface"]["triangles"] != d["W"]["triangles"]
)PY";
  writeText (DIR + "check_w.py", check);
  EXPECT_EQ (std::system (("python3 " + DIR + "check_w.py " + DIR + "default.json " + DIR + "raw.json").c_str ()), 0);
}

/** Every input format, broken in every way a file can be: empty, binary junk, truncated,
  * wrong counts, garbage numbers; plus headers declaring more data than the file holds. */
std::vector<std::pair<std::string, std::string>>
malformedFiles ()
{
  const std::string junk ("\x7f\x45\x00\x01\xff\xfe garbage \x00\x02\x03", 18);
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nend_header\n";
  const std::string pcd = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\n"
                          "POINTS 3\nDATA ascii\n";
  return {
      {"empty.xyz", ""},
      {"junk.xyz", junk},
      {"comments.xyz", "# nothing\n\n"},
      {"garbage.xyz", "1 2 3\n4 five 6\n"},
      {"columns.xyz", "1 2 3\n4 5 6 7\n"},
      {"mixed_columns.xyz", "1 2 3\n4 5 6 0 0 1\n"},
      {"empty.off", ""},
      {"junk.off", junk},
      {"truncated.off", "OFF\n10 0 0\n1 2 3\n4 5 6\n"},
      {"noheader.off", "3 0 0\n1 2 3\n"},
      {"count.off", "OFF\n-4 0 0\n"},
      {"garbage.off", "OFF\n2 0 0\n1 2 3\n4 x 6\n"},
      {"empty.obj", ""},
      {"junk.obj", junk},
      {"novertex.obj", "f 1 2 3\n"},
      {"short.obj", "v 1 2\n"},
      {"garbage.obj", "v 1 2 3\nv 1 zwei 3\n"},
      {"empty.ply", ""},
      {"junk.ply", junk},
      {"truncated.ply", ply + "0 0 0\n1 0 0\n"},
      {"truncated_binary.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 100\nproperty float x\n"
                               "property float y\nproperty float z\nend_header\n\x01\x02"},
      {"garbage.ply", ply + "0 0 0\n1 x 0\n0 1 0\n"},
      {"huge_ascii.ply", "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nproperty float y\n"
                         "property float z\nend_header\n0 0 0\n"},
      {"no_properties.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 99999999999993\nend_header\n"},
      {"glued_end_header.ply",
       "ply\nformat binary_little_endian 1.0\nend_headerelement vertex 99999999999993\nend_header\n"},
      {"green_before_red.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                               "property float z\nproperty uchar green\nproperty uchar red\nend_header\n0 0 0 1 2\n"},
      {"vertex_list.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 2\nproperty list uchar uchar l\n"
                          "property float x\nproperty float y\nproperty float z\nend_header\n" +
                              std::string ("\x01\x00", 2) + std::string (12, '\0') +
                              std::string ("\x03\x00\x00\x00", 4) + std::string (12, '\0')},
      {"nofields.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float u\nend_header\n0\n"},
      {"empty.pcd", ""},
      {"junk.pcd", junk},
      {"truncated.pcd", pcd + "0 0 0\n"},
      {"blank_header_line.pcd", "\n \n# .PCD v0.7\n" + pcd + "0 0 0\n1 0 0\n0 1 0\n"},
      {"garbage.pcd", pcd + "0 0 0\n1 x 0\n0 1 0\n"},
      {"fields.pcd",
       "VERSION 0.7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 0\n"},
      {"count.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 3\nHEIGHT 1\nPOINTS 5\nDATA ascii\n"},
      {"huge_ascii.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2000000000\nHEIGHT 1\n"
                         "POINTS 2000000000\nDATA ascii\n0 0 0\n"},
      {"huge.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2000000000\nHEIGHT 1\n"
                   "POINTS 2000000000\nDATA binary\n\x01\x02"},
      {"keyword_data.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nHEIGHT 1\n"
                           "POINTS 3\nDATA binary\nCOLUMNS y x z\n" +
                               std::string (40, '0')}, // PCL: y and x swapped
      {"points.las", "1 2 3\n"},
  };
}

TEST_F (Cli, MalformedInputGivesOneErrorLineAndNoOutput)
{
  auto files = malformedFiles ();
  files.push_back ({"missing.xyz", ""});
  for (const auto& [name, content] : files)
  {
    SCOPED_TRACE (name);
    if (name != "missing.xyz")
      writeText (DIR + name, content);
    std::remove ((DIR + "never.ply").c_str ());
    const CliRun run = runCli (DIR + name + " " + DIR + "never.ply");
    EXPECT_NE (run.status, 0);
    EXPECT_FALSE (exists (DIR + "never.ply"));
    EXPECT_EQ (std::count (run.err.begin (), run.err.end (), '\n'), 1) << run.err;
    EXPECT_NE (run.err.find (name), std::string::npos) << "the error names the file: " << run.err;
  }
}

TEST_F (Cli, UnwritableOutputGivesOneErrorLine)
{
  writeText (DIR + "unwritable.xyz", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  const CliRun run = runCli (DIR + "unwritable.xyz " + DIR + "no/such/dir/out.ply");
  EXPECT_EQ (run.status, 1);
  EXPECT_EQ (std::count (run.err.begin (), run.err.end (), '\n'), 1) << run.err;
  EXPECT_NE (run.err.find ("out.ply"), std::string::npos);
}

TEST_F (Cli, WeightsFromXyzColumnOrPcdField)
{
  // Four heavy corners (weight 10) around a light centre: the centre is hidden.
  writeText (DIR + "weighted.xyz", "1 1 1 10\n1 -1 -1 10\n-1 1 -1 10\n-1 -1 1 10\n0 0 0 0\n");
  pcl::PointCloud<pcl::PointXYZI> cloud;
  for (const auto& [x, y, z, w] : std::vector<std::array<float, 4>>{{1, 1, 1, 10}, {1, -1, -1, 10}, {-1, 1, -1, 10},
                                                                     {-1, -1, 1, 10}, {0, 0, 0, 0}})
  {
    pcl::PointXYZI p;
    p.x = x, p.y = y, p.z = z, p.intensity = w;
    cloud.push_back (p);
  }
  ASSERT_EQ (pcl::io::savePCDFileASCII (DIR + "weighted.pcd", cloud), 0);
  const auto statsOf = [] (const std::string& arguments) {
    std::remove ((DIR + "stats.json").c_str ());
    const CliRun run = runCli (arguments + " " + DIR + "w.ply --stats-json " + DIR + "stats.json");
    EXPECT_EQ (run.status, 0) << run.err;
    std::ifstream in (DIR + "stats.json");
    return std::string ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  };
  // Without --weight-field a PCD input has no weights: nothing is hidden.
  EXPECT_NE (statsOf (DIR + "weighted.pcd").find ("\"hidden\":[]"), std::string::npos);
  // Nor a .xyz file's 4th column without --weights-column: it is a field (an intensity, say).
  EXPECT_NE (statsOf (DIR + "weighted.xyz").find ("\"hidden\":[]"), std::string::npos);
  // With the field named, and from the 4th column when asked, the centre is hidden.
  for (const std::string arguments :
       {DIR + "weighted.xyz --weights-column", DIR + "weighted.pcd --weight-field intensity"})
    EXPECT_NE (statsOf (arguments).find ("\"hidden\":[4]"), std::string::npos) << arguments;
  // --weight-scale 0 is the unweighted wrap: nothing hidden.
  EXPECT_NE (statsOf (DIR + "weighted.xyz --weights-column --weight-scale 0").find ("\"hidden\":[]"),
             std::string::npos);
  // A non-finite weight skips its point, with a warning, as a non-finite coordinate does.
  writeText (DIR + "nanweight.xyz", "1 1 1 0\n1 -1 -1 0\n-1 1 -1 nan\n-1 -1 1 0\n0 0 0 0\n");
  const std::string nan = statsOf (DIR + "nanweight.xyz --weights-column");
  EXPECT_NE (nan.find ("\"skipped\":1"), std::string::npos) << nan;
  const CliRun warned = runCli (DIR + "nanweight.xyz " + DIR + "w.ply --weights-column");
  EXPECT_EQ (warned.status, 0);
  EXPECT_NE (warned.err.find ("1 point skipped"), std::string::npos) << warned.err;

  // Errors: a field for a text file, a column for a PCD file, no 4th column, a missing field, a
  // bad scale.
  writeText (DIR + "three.xyz", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  EXPECT_EQ (runCli (DIR + "weighted.xyz " + DIR + "w.ply --weight-field intensity").status, 1);
  EXPECT_EQ (runCli (DIR + "weighted.pcd " + DIR + "w.ply --weights-column").status, 1);
  EXPECT_EQ (runCli (DIR + "three.xyz " + DIR + "w.ply --weights-column").status, 1);
  EXPECT_EQ (runCli (DIR + "weighted.pcd " + DIR + "w.ply --weight-field curvature").status, 1);
  EXPECT_EQ (runCli (DIR + "weighted.xyz " + DIR + "w.ply --weights-column --weight-scale inf").status, 2);
}

TEST_F (Cli, SinkDeletionOptions)
{
  writeText (DIR + "torus1000.xyz", xyzText (torusSample (1000, 2)));
  for (const std::string options :
       {"--radius 0.45", "--delta 0.2 --mode front", "--radius-rel 4 --mode global", "--sinks 3",
        "--delta 0.2 --region sphere:0,0,0,0.7", "--delta 0.2 --region box:-.7,-.7,-.5,.7,.7,.5"})
  {
    SCOPED_TRACE (options);
    const CliRun run =
        runCli (DIR + "torus1000.xyz " + DIR + "opened.ply --stats-json " + DIR + "opened.json " + options);
    ASSERT_EQ (run.status, 0) << run.err;
    writeText (DIR + "deleted.py", "import json, sys\n"
                                   "s = json.load(open(sys.argv[1])); d = s['deletion']\n"
                                   "assert d['deleted'] >= 1 and d['sinks'] > 0 and s['spacing'] > 0, s\n");
    EXPECT_EQ (std::system (("python3 " + DIR + "deleted.py " + DIR + "opened.json").c_str ()), 0);
  }
  for (const std::string bad : {"--radius -1", "--radius-rel 0", "--mode sideways", "--sinks 0", "--delta x",
                                "--delta 1 --region sphere:0,0,0", "--delta 1 --region box:1,0,0,0,1,1",
                                "--delta 1 --region cube:0,0,0,1", "--delta 1 --region sphere:0,0,nan,1",
                                "--delta 1 --region sphere:0,0,0,1,", "--region sphere:0,0,0,1",
                                "--delta 1 --mode global --region sphere:0,0,0,1", "--delta 1 --radius-rel 4",
                                "--sinks 3 --radius 0.45"})
    EXPECT_EQ (runCli (DIR + "torus1000.xyz " + DIR + "opened.ply " + bad).status, 2) << bad;
}

TEST_F (Cli, ManifoldOptionAppendsCopiesAndGivesAClosedManifold)
{
  const auto torus = torusSample (200, 1); // sealed, with pinch edges
  writeText (DIR + "torus200.xyz", xyzText (torus));
  for (const std::string format : {".ply", ".obj", ".vtk"})
  {
    SCOPED_TRACE (format);
    const CliRun run = runCli (DIR + "torus200.xyz " + DIR + "manifold" + format + " --raw --manifold --stats-json " +
                               DIR + "manifold.json");
    ASSERT_EQ (run.status, 0) << run.err;
    pcl::PolygonMesh mesh;
    if (format == ".ply")
      ASSERT_GE (pcl::io::loadPLYFile (DIR + "manifold.ply", mesh), 0);
    else if (format == ".obj")
      ASSERT_GE (pcl::io::loadOBJFile (DIR + "manifold.obj", mesh), 0);
    else
      ASSERT_GT (pcl::io::loadPolygonFileVTK (DIR + "manifold.vtk", mesh), 0);
    const std::size_t vertices = std::size_t (mesh.cloud.width) * mesh.cloud.height;
    EXPECT_GT (vertices, torus.size ()) << "copies follow the input points";
    const std::vector<Triangle> triangles = trianglesOf (mesh.polygons);
    ASSERT_EQ (triangles.size (), mesh.polygons.size ());
    for (const auto& t : triangles)
      for (auto v : t)
        ASSERT_LT (std::size_t (v), vertices);
    // Every edge in exactly two triangles, once each way, every vertex's triangles one fan.
    const SurfaceReport s = describeSurface (triangles);
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
    writeText (DIR + "copies.py",
               "import json, sys\n"
               "m = json.load(open(sys.argv[1]))['manifold']\n"
               "assert m['pinch_edges_split'] > 0 and len(m['copies']) == int(sys.argv[2]) - 200, m\n");
    EXPECT_EQ (std::system (
                   ("python3 " + DIR + "copies.py " + DIR + "manifold.json " + std::to_string (vertices)).c_str ()),
               0);
  }
}

TEST_F (Cli, TerrainIsOneOpenSheetOrClosedWhenAsked)
{
  const auto terrain = terrainSample (3000, 2);
  writeText (DIR + "terrain.xyz", xyzText (terrain));
  const CliRun sheet = runCli (DIR + "terrain.xyz " + DIR + "sheet.ply");
  ASSERT_EQ (sheet.status, 0) << sheet.err;
  pcl::PolygonMesh mesh;
  ASSERT_GE (pcl::io::loadPLYFile (DIR + "sheet.ply", mesh), 0);
  EXPECT_EQ (std::size_t (mesh.cloud.width) * mesh.cloud.height, terrain.size ()) << "no point copied";
  const OpenSurfaceReport open = describeOpenSurface (trianglesOf (mesh.polygons));
  EXPECT_TRUE (open.manifold);
  EXPECT_TRUE (open.consistently_oriented);
  EXPECT_GT (open.boundary_edges, 0u);

  const CliRun closed = runCli (DIR + "terrain.xyz " + DIR + "closed.ply --closed");
  ASSERT_EQ (closed.status, 0) << closed.err;
  pcl::PolygonMesh shell;
  ASSERT_GE (pcl::io::loadPLYFile (DIR + "closed.ply", shell), 0);
  EXPECT_GT (std::size_t (shell.cloud.width) * shell.cloud.height, terrain.size ()) << "points copied per side";
  EXPECT_TRUE (describeSurface (trianglesOf (shell.polygons)).closed_manifold);
}

TEST_F (Cli, SheetFacesTheViewpointGivenOrThePcdFilesOwn)
{
  const auto terrain = terrainSample (3000, 3);
  // The z of the sheet's summed area normal: + up, - down.
  const auto up = [&] (const std::string& mesh_file) {
    pcl::PolygonMesh mesh;
    EXPECT_GE (pcl::io::loadPLYFile (mesh_file, mesh), 0);
    double z = 0;
    for (const auto& t : trianglesOf (mesh.polygons))
    {
      const Point3 &a = terrain[t[0]], &b = terrain[t[1]], &c = terrain[t[2]];
      z += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    }
    return z;
  };
  writeText (DIR + "facing_terrain.xyz", xyzText (terrain));
  ASSERT_EQ (runCli (DIR + "facing_terrain.xyz " + DIR + "up.ply").status, 0);
  EXPECT_GT (up (DIR + "up.ply"), 0) << "no viewpoint: up";
  ASSERT_EQ (runCli (DIR + "facing_terrain.xyz " + DIR + "below.ply --viewpoint 0,0,-5").status, 0);
  EXPECT_LT (up (DIR + "below.ply"), 0) << "towards a viewpoint below";

  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (const Point3& p : terrain)
    cloud.push_back ({float (p[0]), float (p[1]), float (p[2])});
  cloud.sensor_origin_ = Eigen::Vector4f (0.0f, 0.0f, -5.0f, 0.0f);
  ASSERT_EQ (pcl::io::savePCDFileBinary (DIR + "terrain.pcd", cloud), 0);
  ASSERT_EQ (runCli (DIR + "terrain.pcd " + DIR + "pcd.ply").status, 0);
  EXPECT_LT (up (DIR + "pcd.ply"), 0) << "towards the .pcd file's VIEWPOINT";
  ASSERT_EQ (runCli (DIR + "terrain.pcd " + DIR + "given.ply --viewpoint 0,0,5").status, 0);
  EXPECT_GT (up (DIR + "given.ply"), 0) << "--viewpoint before the file's";
  for (const char* bad : {"0,0", "0,0,0,0", "0,x,1", "0,0,inf", "1:2:3"})
    EXPECT_EQ (runCli (DIR + "facing_terrain.xyz " + DIR + "bad.ply --viewpoint " + bad).status, 2) << bad;
}

/** A sphere's points with a colour, a normal and a curvature each, in every point format. */
pcl::PointCloud<pcl::PointXYZRGBNormal>
colouredSphere (std::size_t n)
{
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  for (const auto& p : sphereSample (n, 6, 1e-3))
  {
    pcl::PointXYZRGBNormal q;
    q.x = float (p[0]), q.y = float (p[1]), q.z = float (p[2]);
    q.r = std::uint8_t (cloud.size () % 251), q.g = std::uint8_t (cloud.size () % 7), q.b = 200;
    q.normal_x = float (p[0]), q.normal_y = float (p[1]), q.normal_z = float (p[2]);
    q.curvature = float (cloud.size ()) / 8;
    cloud.push_back (q);
  }
  return cloud;
}

TEST_F (Cli, ColoursNormalsAndFieldsReachTheOutputVertices)
{
  const auto cloud = colouredSphere (600);
  ASSERT_EQ (pcl::io::savePCDFileBinary (DIR + "coloured.pcd", cloud), 0);
  ASSERT_EQ (pcl::io::savePLYFileBinary (DIR + "coloured.ply", cloud), 0);
  for (const std::string input : {"coloured.pcd", "coloured.ply"})
  {
    SCOPED_TRACE (input);
    for (const std::string output : {"kept.ply", "kept.obj", "kept.off", "kept.vtk"})
      ASSERT_EQ (runCli (DIR + input + " " + DIR + output + " --quiet").status, 0) << output;
    // .ply: everything, read back by PCL.
    pcl::PolygonMesh mesh;
    ASSERT_GE (pcl::io::loadPLYFile (DIR + "kept.ply", mesh), 0);
    for (const char* field : {"rgb", "normal_x", "normal_y", "normal_z", "curvature"})
      EXPECT_NE (pcl::getFieldIndex (mesh.cloud, field), -1) << field;
    pcl::PointCloud<pcl::PointXYZRGBNormal> back;
    pcl::fromPCLPointCloud2 (mesh.cloud, back);
    ASSERT_EQ (back.size (), cloud.size ());
    for (std::size_t i = 0; i < cloud.size (); ++i)
      ASSERT_TRUE (back[i].r == cloud[i].r && back[i].g == cloud[i].g && back[i].b == cloud[i].b &&
                   back[i].normal_z == cloud[i].normal_z && back[i].curvature == cloud[i].curvature)
          << i;
    // .obj and .off: colours and normals, read back by the tool's own reader.
    for (const std::string output : {"kept.obj", "kept.off"})
    {
      const apps::PointFile file = apps::readPointFile (DIR + output);
      ASSERT_EQ (file.attributes.colours.size (), cloud.size ()) << output;
      ASSERT_EQ (file.attributes.normals.size (), cloud.size ()) << output;
      for (std::size_t i = 0; i < cloud.size (); ++i)
        ASSERT_TRUE (file.attributes.colours[i][0] == cloud[i].r && file.attributes.colours[i][1] == cloud[i].g &&
                     std::abs (file.attributes.normals[i][0] - cloud[i].normal_x) < 1e-6)
            << output << " " << i;
    }
    // .vtk: point data, and PCL reads the colours.
    std::ifstream vtk (DIR + "kept.vtk");
    const std::string text ((std::istreambuf_iterator<char> (vtk)), std::istreambuf_iterator<char> ());
    for (const char* part : {"POINT_DATA 600", "NORMALS normals float", "COLOR_SCALARS RGB 3", "SCALARS curvature"})
      EXPECT_NE (text.find (part), std::string::npos) << part;
    pcl::PolygonMesh from_vtk;
    ASSERT_GT (pcl::io::loadPolygonFileVTK (DIR + "kept.vtk", from_vtk), 0);
    EXPECT_NE (pcl::getFieldIndex (from_vtk.cloud, "rgba"), -1); // as PCL's VTK reader names it
    pcl::PointCloud<pcl::PointXYZRGBNormal> vtk_points;
    pcl::fromPCLPointCloud2 (from_vtk.cloud, vtk_points);
    ASSERT_EQ (vtk_points.size (), cloud.size ());
    EXPECT_TRUE (vtk_points[123].r == cloud[123].r && vtk_points[123].g == cloud[123].g);
  }
}

TEST_F (Cli, XyzColumnsBecomeNormalsColoursOrFields)
{
  const auto points = sphereSample (400, 8, 1e-3);
  std::ostringstream normals, colours, four;
  normals.precision (17), colours.precision (17), four.precision (17);
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    const Point3& p = points[i];
    const double length = std::sqrt (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    normals << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << p[0] / length << ' ' << p[1] / length << ' '
            << p[2] / length << '\n';
    colours << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << i % 256 << " 0 255\n";
    four << p[0] << ' ' << p[1] << ' ' << p[2] << ' ' << 1000.5 + double (i) << '\n';
  }
  writeText (DIR + "normals.xyz", normals.str ());
  writeText (DIR + "colours.xyz", colours.str ());
  writeText (DIR + "four.xyz", four.str ());
  const apps::PointFile with_normals = apps::readPointFile (DIR + "normals.xyz");
  EXPECT_EQ (with_normals.attributes.normals.size (), points.size ());
  EXPECT_TRUE (with_normals.attributes.colours.empty () && with_normals.attributes.scalars.empty ());
  const apps::PointFile with_colours = apps::readPointFile (DIR + "colours.xyz");
  ASSERT_EQ (with_colours.attributes.colours.size (), points.size ());
  EXPECT_EQ (with_colours.attributes.colours[300][0], 300 % 256);
  EXPECT_TRUE (with_colours.attributes.normals.empty ());
  // The common LiDAR export, x y z intensity: all points used, the 4th column a vertex field.
  const apps::PointFile with_field = apps::readPointFile (DIR + "four.xyz");
  EXPECT_TRUE (with_field.weights.empty ());
  ASSERT_EQ (with_field.attributes.scalars.size (), 1u);
  EXPECT_EQ (with_field.attributes.scalars[0].name, "field4");
  ASSERT_EQ (runCli (DIR + "four.xyz " + DIR + "four.ply --quiet").status, 0);
  pcl::PolygonMesh mesh;
  ASSERT_GE (pcl::io::loadPLYFile (DIR + "four.ply", mesh), 0);
  EXPECT_EQ (mesh.polygons.size (), 2 * points.size () - 4); // a sphere through every point
  const int field = pcl::getFieldIndex (mesh.cloud, "field4");
  ASSERT_NE (field, -1);
  double value = 0;
  std::memcpy (&value, &mesh.cloud.data[7 * mesh.cloud.point_step + mesh.cloud.fields[field].offset], sizeof value);
  EXPECT_EQ (value, 1007.5);
}

TEST_F (Cli, NonFinitePointsAreLeftOutOfTheOutput)
{
  auto cloud = colouredSphere (300);
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (const std::size_t i : {0, 17, 299})
    cloud[i].x = nan;
  ASSERT_EQ (pcl::io::savePCDFileBinary (DIR + "holes.pcd", cloud), 0);
  const CliRun run = runCli (DIR + "holes.pcd " + DIR + "holes.ply");
  ASSERT_EQ (run.status, 0) << run.err;
  EXPECT_NE (run.err.find ("3 points skipped"), std::string::npos) << run.err;
  pcl::PolygonMesh mesh;
  ASSERT_GE (pcl::io::loadPLYFile (DIR + "holes.ply", mesh), 0);
  pcl::PointCloud<pcl::PointXYZRGBNormal> back;
  pcl::fromPCLPointCloud2 (mesh.cloud, back);
  ASSERT_EQ (back.size (), 297u); // the finite points, in input order, their fields with them
  for (std::size_t i = 0, k = 0; i < cloud.size (); ++i)
    if (std::isfinite (cloud[i].x))
    {
      ASSERT_EQ (back[k].curvature, cloud[i].curvature) << i;
      ASSERT_TRUE (std::isfinite (back[k].x));
      ++k;
    }
  EXPECT_EQ (mesh.polygons.size (), 2 * 297u - 4);
  for (const auto& polygon : mesh.polygons)
    for (const auto v : polygon.vertices)
      ASSERT_LT (v, 297u);
  // No finite point at all, like no point at all: an error, no output.
  writeText (DIR + "all_nan.xyz", "nan 0 0\n0 nan 0\ninf 1 1\n");
  writeText (DIR + "nothing.xyz", "# no points\n");
  for (const std::string input : {"all_nan.xyz", "nothing.xyz"})
  {
    std::remove ((DIR + "none.ply").c_str ());
    const CliRun none = runCli (DIR + input + " " + DIR + "none.ply");
    EXPECT_EQ (none.status, 1) << input;
    EXPECT_NE (none.err.find (input), std::string::npos) << none.err;
    EXPECT_FALSE (exists (DIR + "none.ply")) << input;
  }
}

TEST_F (Cli, ProgressOnStderrWhenAskedOrOnATerminal)
{
  // Enough points for the triangulation to report its progress within.
  writeText (DIR + "progress.xyz", xyzText (sphereSample (120000, 9, 1e-3)));
  const CliRun shown = runCli (DIR + "progress.xyz " + DIR + "progress.ply --progress");
  ASSERT_EQ (shown.status, 0) << shown.err;
  for (const char* line : {"pcl_wrap: 120000 points from", "  triangulation   25 %", "  triangulation   75 %",
                           "  collapse", "pcl_wrap: wrote "})
    EXPECT_NE (shown.err.find (line), std::string::npos) << line << " in:\n" << shown.err;
  // Not a terminal and not asked: nothing on stderr. Inserted in rounds to report progress or
  // all at once, the points give the same triangulation, and the same surface.
  const CliRun quiet = runCli (DIR + "progress.xyz " + DIR + "quiet.ply");
  ASSERT_EQ (quiet.status, 0);
  EXPECT_EQ (quiet.err, "");
  const auto bytes = [] (const std::string& path) {
    std::ifstream in (path, std::ios::binary);
    return std::string ((std::istreambuf_iterator<char> (in)), std::istreambuf_iterator<char> ());
  };
  EXPECT_EQ (bytes (DIR + "progress.ply"), bytes (DIR + "quiet.ply"));
  EXPECT_EQ (runCli (DIR + "progress.xyz " + DIR + "progress.ply --progress --quiet").status, 2);
}

TEST_F (Cli, UsageErrors)
{
  // A regular tetrahedron: its circumcentre is inside, it is a sink, and its wrap is its 4 faces.
  writeText (DIR + "ok.xyz", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  EXPECT_EQ (runCli (DIR + "ok.xyz").status, 2);
  EXPECT_EQ (runCli (DIR + "ok.xyz " + DIR + "usage.dxf").status, 2);
  EXPECT_EQ (runCli (DIR + "ok.xyz " + DIR + "usage.ply --bogus").status, 2);
  EXPECT_EQ (runCli (DIR + "ok.xyz " + DIR + "usage.ply --threads x").status, 2);
  EXPECT_EQ (runCli ("--help").status, 0);
  FILE* version = popen ((std::string (PCL_WRAP_CLI) + " --version").c_str (), "r");
  ASSERT_NE (version, nullptr);
  char line[128] = {};
  const bool read = std::fgets (line, sizeof line, version) != nullptr;
  EXPECT_EQ (pclose (version), 0);
  EXPECT_TRUE (read && std::string (line).rfind ("pcl_wrap 0.", 0) == 0) << line;
  // --manifold splits the raw W: without --raw it would do nothing, so it is refused.
  const CliRun manifold = runCli (DIR + "ok.xyz " + DIR + "usage.ply --manifold");
  EXPECT_EQ (manifold.status, 2);
  EXPECT_NE (manifold.err.find ("--raw"), std::string::npos) << manifold.err;
  EXPECT_FALSE (exists (DIR + "usage.ply"));
  // --closed chooses how the default surface treats a single layer: nothing to choose for --raw.
  const CliRun closed = runCli (DIR + "ok.xyz " + DIR + "usage.ply --raw --closed");
  EXPECT_EQ (closed.status, 2);
  EXPECT_NE (closed.err.find ("--closed"), std::string::npos) << closed.err;
  EXPECT_FALSE (exists (DIR + "usage.ply"));
  // Writing over the input, under its own name or another, is refused and leaves it as it was.
  writeText (DIR + "same.xyz", "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  for (const std::string& output : {"same.xyz", "./same.xyz"})
  {
    const CliRun same = runCli (DIR + "same.xyz " + DIR + output);
    EXPECT_EQ (same.status, 2) << output;
    EXPECT_NE (same.err.find ("input"), std::string::npos) << same.err;
  }
  EXPECT_EQ (runCli (DIR + "same.xyz " + DIR + "same.ply --stats-json " + DIR + "same.xyz").status, 2);
  std::ifstream same (DIR + "same.xyz");
  std::stringstream text;
  text << same.rdbuf ();
  EXPECT_EQ (text.str (), "1 1 1\n1 -1 -1\n-1 1 -1\n-1 -1 1\n");
  const CliRun ok = runCli (DIR + "ok.xyz " + DIR + "tet.obj --threads 1");
  EXPECT_EQ (ok.status, 0) << ok.err;
  std::ifstream tet (DIR + "tet.obj");
  int faces = 0;
  for (std::string line; std::getline (tet, line);)
    faces += line.rfind ("f ", 0) == 0;
  EXPECT_EQ (faces, 4);
}

} // namespace
} // namespace pcl_wrap::test
