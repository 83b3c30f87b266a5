// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// bench_wrap SHAPE N [SEED [RUNS]]: on the same N points (SHAPE: sphere, cube or torus, or a point
// file), times and measures the peak memory of CGAL's triangulations alone (the floor any
// Delaunay-based method pays) and of pcl_wrap, stage by stage: its default output, the raw W,
// the raw W of a tighter wrap (--radius-rel 4, front deletion), and the raw W with a progress
// observer (as the command line and Python run it: from 100,000 points the triangulation then
// inserts the points in rounds, to report how far it has come). Each measurement runs in a
// child process of its own, so each peak resident set size is its own. With RUNS > 1 they
// take turns RUNS times and each reports its fastest run: a shared machine's speed can drift by
// 20-30% over minutes, and taking turns exposes them all to the same drift. The ratio of pcl_wrap to
// the regular triangulation within each turn is printed too: its spread says how far one
// run's ratio can be trusted. CGAL's parallel Delaunay triangulation (all threads, the lock grid
// pcl_wrap uses) is timed once more, after the turns: on equal weights pcl_wrap's triangulation
// stage is that insertion plus reading and ordering the cells, so it is the floor of any
// parallel pipeline.
//
// Before each measurement, as much memory as the largest peak so far (at first a guess from N)
// is written and freed, unless the fifth argument is "cold": see warmMemory().
#include "bench_points.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/worker_threads.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Spatial_lock_grid_3.h>

#include <tbb/info.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <cstring>
#include <functional>
#include <iostream>
#include <string>
#include <vector>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{

using pcl_wrap::Point3;
constexpr double TIGHTER = 4.0; // the relative radius of the tighter wrap timed (front deletion)
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Measurement
{
  double seconds = 0.0;
  long peak_kib = 0;
  char detail[512] = "";
};

/** Writes to every page of \a bytes of fresh memory, then frees it.
  *
  * This project's VMs report freed memory to their host (Linux's free page reporting, about two
  * seconds after it is freed), and the first touch of a reported page waits for the host: 0.5-2
  * s per GB, against under 0.1 s for a page freed just before. Unwarmed, a measurement pays that
  * for whatever part of its memory the process before it did not just free, so its time
  * depended on what ran before it. Warmed, each starts from recently freed pages, as on a
  * machine without such reporting. */
void
warmMemory (std::size_t bytes)
{
  void* p = ::mmap (nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED)
    return;
  ::madvise (p, bytes, MADV_HUGEPAGE); // as pcl_wrap's arrays
  for (std::size_t i = 0; i < bytes; i += 4096)
    static_cast<volatile char*> (p)[i] = 1;
  ::munmap (p, bytes);
}

/** Runs \a work in a child process, after warming \a warm bytes of memory; returns its wall
  * time and peak resident set size. */
Measurement
measure (const std::function<void (Measurement&)>& work, std::size_t warm = 0)
{
  if (warm > 0)
    warmMemory (warm);
  int channel[2];
  if (::pipe (channel) != 0)
    throw std::runtime_error ("pipe failed");
  const pid_t child = ::fork ();
  if (child == 0)
  {
    ::close (channel[0]);
    Measurement m;
    const auto start = std::chrono::steady_clock::now ();
    work (m);
    m.seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
    rusage usage{};
    ::getrusage (RUSAGE_SELF, &usage);
    m.peak_kib = usage.ru_maxrss;
    const bool sent = ::write (channel[1], &m, sizeof (m)) == ssize_t (sizeof (m));
    ::_exit (sent ? 0 : 1);
  }
  ::close (channel[1]);
  Measurement m;
  const bool received = ::read (channel[0], &m, sizeof (m)) == ssize_t (sizeof (m));
  ::close (channel[0]);
  int status = 0;
  ::waitpid (child, &status, 0);
  if (!received || !WIFEXITED (status) || WEXITSTATUS (status) != 0)
    throw std::runtime_error ("a measurement failed");
  return m;
}

} // namespace

int
main (int argc, char** argv)
{
  if (argc < 3 || argc > 6 || (argc == 6 && std::strcmp (argv[5], "cold") != 0))
  {
    std::cerr << "usage: bench_wrap sphere|cube|torus|terrain|rough_terrain|half_sphere|FILE N [SEED [RUNS [cold]]]\n";
    return 2;
  }
  const std::string shape = argv[1];
  const std::size_t n = std::stoul (argv[2]);
  const unsigned seed = argc > 3 ? unsigned (std::stoul (argv[3])) : 1u;
  const int runs = argc > 4 ? std::max (1, std::stoi (argv[4])) : 1;
  const bool cold = argc == 6;
  std::vector<Point3> points;
  try
  {
    points = pcl_wrap::bench::makePoints (shape, n, seed);
  }
  catch (const std::exception& e) // an unreadable or malformed file
  {
    std::cerr << "bench_wrap: " << e.what () << "\n";
    return 1;
  }
  // A point file is parsed on all threads, whose workers a forked measurement would not have.
  if (!pcl_wrap::endWorkerThreads ())
  {
    std::cerr << "bench_wrap: the worker threads did not end before the measurements\n";
    return 1;
  }
  // What the process holds before any measurement (the points, the program): subtracted from
  // nothing, shown so the peaks can be read against it.
  const Measurement baseline = measure ([] (Measurement&) {});

  const auto cgalPoints = [&] {
    std::vector<K::Point_3> p;
    p.reserve (points.size ());
    for (const auto& q : points)
      p.emplace_back (q[0], q[1], q[2]);
    return p;
  };
  const auto delaunayAlone = [&] (Measurement& m) {
    const std::vector<K::Point_3> p = cgalPoints ();
    CGAL::Delaunay_triangulation_3<K> dt (p.begin (), p.end ());
    std::snprintf (m.detail, sizeof (m.detail), "%zu cells", std::size_t (dt.number_of_finite_cells ()));
  };
  const auto regularAlone = [&] (Measurement& m) {
    std::vector<K::Weighted_point_3> p;
    p.reserve (points.size ());
    for (const auto& q : points)
      p.emplace_back (K::Point_3 (q[0], q[1], q[2]), 0.0);
    CGAL::Regular_triangulation_3<K> rt (p.begin (), p.end ());
    std::snprintf (m.detail, sizeof (m.detail), "%zu cells", std::size_t (rt.number_of_finite_cells ()));
  };
  const auto delaunayParallel = [&] (Measurement& m) {
    using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                                     CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>;
    using LockGrid = CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking>;
    const std::vector<K::Point_3> p = cgalPoints ();
    LockGrid locks (CGAL::bbox_3 (p.begin (), p.end ()), 50); // as pcl_wrap's
    CGAL::Delaunay_triangulation_3<K, Tds, CGAL::Default, LockGrid> dt (p.begin (), p.end (), &locks);
    std::snprintf (m.detail, sizeof (m.detail), "%zu cells", std::size_t (dt.number_of_finite_cells ()));
  };
  const auto wrapAll = [&] (Measurement& m, pcl_wrap::Output output, double radius_rel, bool observed = false) {
    pcl_wrap::WrapParameters parameters;
    parameters.keep_complex = false;
    parameters.output = output;
    if (radius_rel > 0)
      parameters.threshold = pcl_wrap::Threshold::relativeRadius (radius_rel);
    // Observed, the triangulation reports its progress (as the command line and Python do).
    const pcl_wrap::WrapResult r = observed ? pcl_wrap::computeWrap (points, std::vector<double> (points.size (), 0.0),
                                                                     parameters, {}, [] (const std::string&, double) {})
                                            : pcl_wrap::computeWrap (points, parameters);
    std::string stages;
    for (const auto& t : r.statistics.timings)
      stages += t.stage + "=" + std::to_string (t.seconds) + " ";
    std::snprintf (m.detail, sizeof (m.detail), "%zu W triangles; %s", r.statistics.w_triangles, stages.c_str ());
  };
  // The fastest run of each (with its own details); the largest peak of each.
  const auto keepBest = [] (Measurement& best, const Measurement& m) {
    const long peak = std::max (best.peak_kib, m.peak_kib);
    if (best.seconds == 0.0 || m.seconds < best.seconds)
      best = m;
    best.peak_kib = peak;
  };
  // Warm as much as the largest peak so far (at first about pcl_wrap's at 1M points, scaled),
  // at most half the memory available now.
  const std::size_t available = std::size_t (::sysconf (_SC_AVPHYS_PAGES)) * std::size_t (::sysconf (_SC_PAGESIZE));
  std::size_t warm = cold ? 0 : std::min (points.size () * 1200, available / 2);
  const auto measured = [&] (const std::function<void (Measurement&)>& work) {
    const Measurement m = measure (work, warm);
    if (!cold)
      warm = std::min (std::max (warm, std::size_t (m.peak_kib) * 1024), available / 2);
    return m;
  };
  const auto surface = [&] (Measurement& m) { wrapAll (m, pcl_wrap::Output::surface, 0); };
  const auto raw = [&] (Measurement& m) { wrapAll (m, pcl_wrap::Output::raw, 0); };
  const auto tighter = [&] (Measurement& m) { wrapAll (m, pcl_wrap::Output::raw, TIGHTER); };
  const auto observed = [&] (Measurement& m) { wrapAll (m, pcl_wrap::Output::raw, 0, true); };
  Measurement delaunay, regular, wrap, wrap_raw, wrap_tighter, wrap_observed;
  std::vector<double> turn_ratios, raw_ratios, tighter_ratios, observed_ratios;
  for (int run = 0; run < runs; ++run)
  {
    keepBest (delaunay, measured (delaunayAlone));
    const Measurement r = measured (regularAlone), w = measured (surface), wr = measured (raw), wt = measured (tighter),
                      wo = measured (observed);
    keepBest (regular, r);
    keepBest (wrap, w);
    keepBest (wrap_raw, wr);
    keepBest (wrap_tighter, wt);
    keepBest (wrap_observed, wo);
    turn_ratios.push_back (w.seconds / r.seconds);
    raw_ratios.push_back (w.seconds / wr.seconds);
    tighter_ratios.push_back (wt.seconds / wr.seconds);
    observed_ratios.push_back (wo.seconds / wr.seconds);
  }
  const Measurement parallel = measured (delaunayParallel);
  const std::string parallel_name = "  the same, on " + std::to_string (tbb::info::default_concurrency ()) + " threads";

  std::printf ("%s n=%zu seed=%u, best of %d run%s (baseline peak %.1f MiB; %s)\n", shape.c_str (), points.size (),
               seed, runs, runs == 1 ? "" : "s", baseline.peak_kib / 1024.0,
               cold ? "cold: no memory warmed"
                    : ("memory warmed before each, up to " + std::to_string (warm >> 20) + " MiB").c_str ());
  std::printf ("  %-28s %9s %11s  %s\n", "", "seconds", "peak MiB", "");
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "CGAL Delaunay_triangulation_3", delaunay.seconds,
               delaunay.peak_kib / 1024.0, delaunay.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", parallel_name.c_str (), parallel.seconds, parallel.peak_kib / 1024.0,
               parallel.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "CGAL Regular_triangulation_3", regular.seconds, regular.peak_kib / 1024.0,
               regular.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "pcl_wrap total", wrap.seconds, wrap.peak_kib / 1024.0, wrap.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "pcl_wrap raw W (--raw)", wrap_raw.seconds, wrap_raw.peak_kib / 1024.0,
               wrap_raw.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "pcl_wrap raw, --radius-rel 4", wrap_tighter.seconds,
               wrap_tighter.peak_kib / 1024.0, wrap_tighter.detail);
  std::printf ("  %-28s %9.3f %11.1f  %s\n", "pcl_wrap raw, observed", wrap_observed.seconds,
               wrap_observed.peak_kib / 1024.0, wrap_observed.detail);
  std::printf ("  ratio to regular triangulation: time %.2fx, peak memory %.2fx\n", wrap.seconds / regular.seconds,
               double (wrap.peak_kib) / double (regular.peak_kib));
  std::printf ("  surface against raw W: time %.2fx (per turn:", wrap.seconds / wrap_raw.seconds);
  for (double r : raw_ratios)
    std::printf (" %.2fx", r);
  std::printf ("), peak memory %.2fx\n", double (wrap.peak_kib) / double (wrap_raw.peak_kib));
  std::printf ("  --radius-rel 4 against raw W: time %.2fx (per turn:", wrap_tighter.seconds / wrap_raw.seconds);
  for (double r : tighter_ratios)
    std::printf (" %.2fx", r);
  std::printf ("), peak memory %.2fx\n", double (wrap_tighter.peak_kib) / double (wrap_raw.peak_kib));
  std::printf ("  observed against raw W: time %.2fx (per turn:", wrap_observed.seconds / wrap_raw.seconds);
  for (double r : observed_ratios)
    std::printf (" %.2fx", r);
  std::printf (")\n");
  if (runs > 1)
  {
    std::printf ("  time ratio within each turn:");
    for (double r : turn_ratios)
      std::printf (" %.2fx", r);
    std::sort (turn_ratios.begin (), turn_ratios.end ());
    const std::size_t m = turn_ratios.size ();
    std::printf (" (median %.2fx)\n", m % 2 ? turn_ratios[m / 2] : (turn_ratios[m / 2 - 1] + turn_ratios[m / 2]) / 2);
  }
  return 0;
}
