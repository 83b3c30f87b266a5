// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// computeWrap: checks the parameters, then runs detail::WrapEngine, whose stages are the
// pipeline (points -> triangulation -> complex -> classification -> retraction -> surface), in a
// task arena of the requested size.
#include <pcl_wrap/compute_wrap.h>

#include "wrap_engine.h"

#include <tbb/task_arena.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace pcl_wrap
{

const char*
toString (SimplexClass c)
{
  switch (c)
  {
  case SimplexClass::centered: return "centered";
  case SimplexClass::confident: return "confident";
  case SimplexClass::equivocal: return "equivocal";
  }
  return "?";
}

std::vector<PointIndex>
WrapResult::xSimplices (int k) const
{
  std::vector<PointIndex> out;
  if (k < 0 || k > 3)
    return out;
  const SimplexList& list = complex[k];
  for (std::size_t s = 0; s < list.size (); ++s)
    if (list.in_x[s])
      out.insert (out.end (), list.vertices.begin () + (k + 1) * s, list.vertices.begin () + (k + 1) * (s + 1));
  return out;
}

void
checkParameters (const WrapParameters& p)
{
  const Threshold& t = p.threshold;
  if (t.kind () == Threshold::Kind::size && std::isnan (t.value ()))
    throw std::invalid_argument ("the threshold size is NaN");
  if (t.kind () == Threshold::Kind::relative_radius && !(t.value () > 0 && std::isfinite (t.value ())))
    throw std::invalid_argument ("a relative radius must be finite and > 0");
  if (t.kind () == Threshold::Kind::largest && t.count () == 0)
    throw std::invalid_argument ("the largest sinks: a count >= 1");
  if (!std::isfinite (p.weight_scale))
    throw std::invalid_argument ("weight_scale must be finite");
  if (p.viewpoint &&
      !(std::isfinite ((*p.viewpoint)[0]) && std::isfinite ((*p.viewpoint)[1]) && std::isfinite ((*p.viewpoint)[2])))
    throw std::invalid_argument ("the viewpoint must be finite");
  const Region& r = p.region;
  if (r.shape == Region::Shape::everywhere)
    return;
  for (double v : r.values)
    if (!std::isfinite (v))
      throw std::invalid_argument ("region coordinates must be finite");
  if (r.shape == Region::Shape::sphere && r.values[3] < 0)
    throw std::invalid_argument ("region sphere radius must be >= 0");
  if (r.shape == Region::Shape::box && !(r.values[0] <= r.values[3] && r.values[1] <= r.values[4] &&
                                         r.values[2] <= r.values[5]))
    throw std::invalid_argument ("region box corners must be lowest then highest");
  if (p.deletion != SinkDeletion::front || t.kind () == Threshold::Kind::largest)
    throw std::invalid_argument ("a region (local modification) works with front deletion only");
  if (!t.deletes ())
    throw std::invalid_argument ("a region (local modification) needs a size threshold");
}

WrapResult
computeWrap (const std::vector<Point3>& points, const WrapParameters& parameters, const StageObserver& observer)
{
  return computeWrap (points, {}, parameters, observer);
}

WrapResult
computeWrap (const std::vector<Point3>& points, const std::vector<double>& weights, const WrapParameters& parameters,
             const StageObserver& observer, const ProgressObserver& progress)
{
  checkParameters (parameters);
  if (!weights.empty () && weights.size () != points.size ())
    throw std::invalid_argument ("computeWrap: " + std::to_string (weights.size ()) + " weights for " +
                                 std::to_string (points.size ()) + " points");
  const auto compute = [&] { return detail::WrapEngine (points, weights, parameters, observer, progress).run (); };
  if (parameters.num_threads == 0)
    return compute ();
  // A thread count of its own, for this call only: other TBB users in the process keep theirs.
  tbb::task_arena arena (static_cast<int> (parameters.num_threads));
  WrapResult result;
  arena.execute ([&] { result = compute (); });
  return result;
}

} // namespace pcl_wrap
