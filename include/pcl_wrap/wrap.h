// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/wrap_parameters.h>
#include <pcl_wrap/wrap_result.h>

#include <pcl/surface/reconstruction.h>

#include <string>
#include <vector>

namespace pcl_wrap
{

/** \brief Edelsbrunner's Wrap surface reconstruction as a PCL surface reconstruction stage.
  *
  * Turns an unorganised cloud, with no normals and no parameters to tune, into a surface through
  * the points. The construction is the paper's: the Delaunay complex collapsed from the outside
  * in along the flow of empty spheres leaves X, whose boundary is W. The default output is the
  * default surface built on it, a closed, oriented 2-manifold through the points, or for a single
  * layer one open sheet (docs/surface.md); setOutput (Output::raw) gives W as it is. Every polygon
  * indexes the input cloud (PCL's convention: \c output.cloud is the whole input, organised clouds
  * keep their layout, \c setIndices selects the points used). Non-finite points are skipped and duplicates kept once; both are reported.
  *
  * \code
  * pcl_wrap::Wrap<pcl::PointXYZ> wrap;
  * wrap.setInputCloud (cloud);
  * pcl::PolygonMesh mesh;
  * wrap.reconstruct (mesh);
  * \endcode
  */
template <typename PointInT>
class Wrap : public pcl::SurfaceReconstruction<PointInT>
{
public:
  using Ptr = pcl::shared_ptr<Wrap<PointInT>>;
  using ConstPtr = pcl::shared_ptr<const Wrap<PointInT>>;

  Wrap () { check_tree_ = false; } // Wrap needs no search tree

  /** \brief Sets every parameter at once.
    * \param[in] parameters the parameters; see WrapParameters for the defaults */
  void setParameters (const WrapParameters& parameters) { parameters_ = parameters; }
  /** \brief The parameters in use. */
  const WrapParameters& getParameters () const { return parameters_; }

  /** \brief Keep the whole complex (Del S with classes and X) in getResult().
    * \param[in] keep true to keep it, false (the default) to save memory and time */
  void setKeepComplex (bool keep) { parameters_.keep_complex = keep; }
  /** \brief Worker threads for the parallel stages (0: all cores).
    * \param[in] num_threads the number of threads */
  void setNumberOfThreads (unsigned num_threads) { parameters_.num_threads = num_threads; }

  /** \brief Wrap tighter: which sinks to delete (default none: the basic wrap). Each of the
    * setters below sets it, replacing what was set before.
    * \param[in] threshold the threshold */
  void setThreshold (const Threshold& threshold) { parameters_.threshold = threshold; }
  /** \brief Wrap tighter: delete sinks (empty spheres) of squared radius larger than \a delta.
    * \param[in] delta the threshold; +inf gives the basic wrap */
  void setDelta (double delta) { parameters_.threshold = Threshold::size (delta); }
  /** \brief Wrap tighter: delete sinks of radius larger than \a radius.
    * \param[in] radius the threshold radius */
  void setRadius (double radius) { parameters_.threshold = Threshold::radius (radius); }
  /** \brief Wrap tighter: delete sinks of radius larger than \a factor times the median
    * nearest-neighbour distance.
    * \param[in] factor the factor, > 0 */
  void setRelativeRadius (double factor) { parameters_.threshold = Threshold::relativeRadius (factor); }
  /** \brief How sinks above a size are deleted: front (default, never carves a cavity) or global.
    * \param[in] mode the mode */
  void setSinkDeletion (SinkDeletion mode) { parameters_.deletion = mode; }
  /** \brief Global deletion of the \a count largest sinks.
    * \param[in] count the number of sinks; 0 gives the basic wrap */
  void setSinks (std::size_t count) { parameters_.threshold = count > 0 ? Threshold::largest (count) : Threshold (); }

  /** \brief Local modification: front deletion starts only from the part of W inside \a region
    * (with the threshold set above).
    * \param[in] region a Region::sphere or Region::box; Region () for the whole surface */
  void setRegion (const Region& region) { parameters_.region = region; }
  /** \brief The surface reconstruct() returns: Output::surface (default), an oriented 2-manifold
    * through the points, closed, or one open sheet for a single layer (a terrain, a scan seen from
    * one side); Output::closed, a single layer too closed (a two-sided shell, its points copied);
    * or Output::raw, the paper's W = Bd X as it is.
    * \param[in] output the output */
  void setOutput (Output output) { parameters_.output = output; }
  /** \brief Where the points were seen from: an open sheet faces it. By default the input's
    * sensor_origin_ when the cloud is organised (a depth image, in its sensor's frame) or the
    * origin is not PCL's (0, 0, 0); otherwise a sheet faces up (+z). */
  void setViewpoint (double x, double y, double z) { parameters_.viewpoint = std::array<double, 3>{x, y, z}; }
  /** \brief With Output::raw: output a closed 2-manifold: pinch edges and vertices split, with
    * copies of their points appended to the output cloud after the input points (an organised
    * cloud then becomes unorganised), sheet triangles once per side.
    * \param[in] manifold true to split (default false: W as it is) */
  void setManifold (bool manifold) { parameters_.manifold = manifold; }

  /** \brief Compute the wrap filtration: getResult().filtration then gives W(delta) for any delta
    * (in cloud indices) by a linear filter, and the kept complex each simplex's value.
    * \param[in] filtration true to compute it (default false) */
  void setFiltration (bool filtration) { parameters_.filtration = filtration; }

  /** \brief Weights (squared radii), one per point of the input cloud (not per index); they
    * take precedence over a weight field. Empty: no weights.
    * \param[in] weights the weights */
  void setWeights (std::vector<double> weights) { weights_ = std::move (weights); }
  /** \brief Reads the weights from this field of the points (e.g. "intensity", "curvature").
    * \param[in] field the field's name; empty: no weights */
  void setWeightField (const std::string& field) { weight_field_ = field; }
  /** \brief Multiplies every weight before use.
    * \param[in] scale the factor (default 1) */
  void setWeightScale (double scale) { parameters_.weight_scale = scale; }

  /** \brief The result of the last reconstruct(): the surface, X, classes, with indices into the
    * input cloud. */
  const WrapResult& getResult () const { return result_; }
  /** \brief The statistics of the last reconstruct(), including timings per stage. */
  const WrapStatistics& getStatistics () const { return result_.statistics; }

protected:
  std::string getClassName () const override { return "Wrap"; }

  /** \brief Adds the surface's triangles to \a output, whose cloud is already the input cloud (plus the
    * copies of a manifold split). */
  void performReconstruction (pcl::PolygonMesh& output) override;

  /** \brief Copies the input cloud to \a points and the surface's triangles to \a polygons. */
  void performReconstruction (pcl::PointCloud<PointInT>& points, std::vector<pcl::Vertices>& polygons) override;

private:
  /** Runs the construction on input_ / indices_ and fills result_ with cloud indices. */
  void computeResult ();
  /** The weights of the points at \a indices: from weights_, the weight field, or none.
    * \throws std::invalid_argument on a size mismatch or a missing field */
  std::vector<double> gatherWeights (const pcl::Indices& indices) const;
  /** computeResult(), or, if the engine fails, a PCL_ERROR and an empty result. */
  bool computeResultOrReport ();
  /** The triangles of result_ as PCL polygons, timed as the "mesh" stage. */
  void appendPolygons (std::vector<pcl::Vertices>& polygons);

  using pcl::SurfaceReconstruction<PointInT>::check_tree_;
  using pcl::SurfaceReconstruction<PointInT>::input_;
  using pcl::SurfaceReconstruction<PointInT>::indices_;

  WrapParameters parameters_;
  std::string weight_field_;
  std::vector<double> weights_;
  WrapResult result_;
};

} // namespace pcl_wrap

#ifdef PCL_NO_PRECOMPILE
#include <pcl_wrap/impl/wrap.hpp>
#endif
