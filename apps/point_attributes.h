// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <pcl/PCLPointCloud2.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief A per-point field other than the coordinates, colours and normals: its name, its type
  * (pcl::PCLPointField's datatype, INT8 to FLOAT64, which PLY has too) and its values. */
struct ScalarField
{
  std::string name;
  std::uint8_t datatype = 8; // FLOAT64
  std::vector<double> values;
};

/** \brief What a point file carries besides x, y and z, one entry per point: kept, so that the
  * output mesh's vertices carry it too. */
struct PointAttributes
{
  std::vector<std::array<std::uint8_t, 4>> colours; ///< empty, or red, green, blue, alpha per point
  bool alpha = false;                               ///< whether the file gave the alpha of colours
  std::vector<std::array<float, 3>> normals;        ///< empty, or one per point
  std::vector<ScalarField> scalars;

  bool empty () const { return colours.empty () && normals.empty () && scalars.empty (); }

  /** \brief The attributes of the points \a rows, in that order. */
  PointAttributes rows (const std::vector<PointIndex>& rows) const;

  /** \brief "colours, normals, fields intensity and label", or "" when there is nothing. */
  std::string describe () const;
};

/** \brief Every field of \a cloud but x, y, z and padding: "rgb"/"rgba" as colours,
  * normal_x/y/z as normals, the others (each element of a field with a count above one) as
  * scalar fields.
  * \throws std::invalid_argument when a field lies beyond the point or the data is short */
PointAttributes
attributesOf (const pcl::PCLPointCloud2& cloud);

} // namespace pcl_wrap::apps
