// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/cloud_copies.h>
#include <pcl_wrap/export.h>
#include <pcl_wrap/point_field.h>
#include <pcl_wrap/wrap.h>

#include <pcl/common/io.h>
#include <pcl/console/print.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <exception>

namespace pcl_wrap
{

template <typename PointInT> std::vector<double>
Wrap<PointInT>::gatherWeights (const pcl::Indices& indices) const
{
  std::vector<double> weights;
  if (!weights_.empty ())
  {
    if (weights_.size () != input_->size ())
      throw std::invalid_argument (std::to_string (weights_.size ()) + " weights for a cloud of " +
                                   std::to_string (input_->size ()) + " points");
    for (const auto i : indices)
      weights.push_back (weights_[i]);
  }
  else if (!weight_field_.empty ())
  {
    const auto fields = pcl::getFields<PointInT> ();
    const auto field = std::find_if (fields.begin (), fields.end (),
                                     [&] (const pcl::PCLPointField& f) { return f.name == weight_field_; });
    if (field == fields.end ())
      throw std::invalid_argument ("the points have no field '" + weight_field_ + "'");
    for (const auto i : indices)
      weights.push_back (readPointField (reinterpret_cast<const std::uint8_t*> (&(*input_)[i]), *field));
  }
  return weights; // a non-finite weight skips its point, as a non-finite coordinate does
}

template <typename PointInT> void
Wrap<PointInT>::computeResult ()
{
  const auto& indices = *indices_;
  std::vector<Point3> points;
  points.reserve (indices.size ());
  for (const auto i : indices)
  {
    const PointInT& p = (*input_)[i];
    points.push_back ({double (p.x), double (p.y), double (p.z)});
  }
  // A sheet faces the sensor where the cloud says where it was: an organised cloud (a depth
  // image) is in its sensor's frame; an unorganised one says so by an origin other than PCL's 0.
  WrapParameters parameters = parameters_;
  const Eigen::Vector4f& origin = input_->sensor_origin_;
  if (!parameters.viewpoint && (input_->isOrganized () || origin.head<3> ().squaredNorm () > 0))
    parameters.viewpoint = std::array<double, 3>{origin[0], origin[1], origin[2]};
  result_ = computeWrap (points, gatherWeights (indices), parameters);

  // Positions in `points` -> indices into the input cloud; copies (manifold) follow the cloud.
  const auto to_cloud = [&] (PointIndex k) {
    return static_cast<PointIndex> (k < indices.size () ? indices[k] : input_->size () + (k - indices.size ()));
  };
  for (WrapSurface* surface : {&result_.surface, &result_.w})
  {
    for (auto& t : surface->triangles)
      for (auto& v : t)
        v = to_cloud (v);
    for (auto& e : surface->dangling_edges)
      e = {std::min (to_cloud (e[0]), to_cloud (e[1])), std::max (to_cloud (e[0]), to_cloud (e[1]))};
    for (auto& v : surface->isolated_vertices)
      v = to_cloud (v);
  }
  for (auto& list : result_.complex)
    for (auto& v : list.vertices)
      v = to_cloud (v);
  for (auto& v : result_.skipped)
    v = to_cloud (v);
  for (auto& v : result_.hidden)
    v = to_cloud (v);
  for (auto& v : result_.copies)
    v = to_cloud (v);
  for (std::vector<PointIndex>* list : {&result_.apart, &result_.off_surface})
  {
    for (auto& v : *list)
      v = to_cloud (v);
    std::sort (list->begin (), list->end ()); // ascending in the cloud, whatever order the indices have
  }
  for (auto& d : result_.duplicates)
    d = {to_cloud (d.first), to_cloud (d.second)};
  if (!result_.filtration.empty ())
    result_.filtration = result_.filtration.reindexed (to_cloud);
}

template <typename PointInT> void
Wrap<PointInT>::appendPolygons (std::vector<pcl::Vertices>& polygons)
{
  const auto start = std::chrono::steady_clock::now ();
  polygons.reserve (polygons.size () + result_.surface.triangles.size ());
  for (const auto& t : result_.surface.triangles)
  {
    pcl::Vertices polygon;
    polygon.vertices.assign (t.begin (), t.end ());
    polygons.push_back (std::move (polygon));
  }
  const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  result_.statistics.timings.push_back ({"mesh", seconds});
  result_.statistics.total_seconds += seconds;
}

template <typename PointInT> bool
Wrap<PointInT>::computeResultOrReport ()
{
  try
  {
    computeResult ();
    return true;
  }
  catch (const std::exception& e)
  {
    PCL_ERROR ("[pcl_wrap::%s::reconstruct] %s\n", getClassName ().c_str (), e.what ());
    result_ = WrapResult ();
    return false;
  }
}

template <typename PointInT> void
Wrap<PointInT>::performReconstruction (pcl::PolygonMesh& output)
{
  if (!computeResultOrReport ())
    return;
  appendPolygons (output.polygons);
  appendCopies (output.cloud, result_.copies);
}

template <typename PointInT> void
Wrap<PointInT>::performReconstruction (pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons)
{
  points = *input_;
  polygons.clear ();
  if (!computeResultOrReport ())
    return;
  appendPolygons (polygons);
  for (const PointIndex c : result_.copies)
    points.push_back (points[c]);
}

} // namespace pcl_wrap

#define PCL_INSTANTIATE_Wrap(T) template class PCL_WRAP_EXPORT pcl_wrap::Wrap<T>;
