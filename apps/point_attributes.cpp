// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_attributes.h"

#include <pcl_wrap/point_field.h>

#include <pcl/common/io.h>

#include <algorithm>

namespace pcl_wrap::apps
{

PointAttributes
PointAttributes::rows (const std::vector<PointIndex>& rows) const
{
  PointAttributes out;
  out.alpha = alpha;
  for (const PointIndex r : rows)
  {
    if (!colours.empty ())
      out.colours.push_back (colours[r]);
    if (!normals.empty ())
      out.normals.push_back (normals[r]);
  }
  for (const ScalarField& field : scalars)
  {
    ScalarField& copy = out.scalars.emplace_back (ScalarField{field.name, field.datatype, {}});
    copy.values.reserve (rows.size ());
    for (const PointIndex r : rows)
      copy.values.push_back (field.values[r]);
  }
  return out;
}

std::string
PointAttributes::describe () const
{
  std::string text;
  const auto add = [&] (const std::string& part) { text += (text.empty () ? "" : ", ") + part; };
  if (!colours.empty ())
    add (alpha ? "colours with alpha" : "colours");
  if (!normals.empty ())
    add ("normals");
  if (!scalars.empty ())
  {
    std::string names;
    for (std::size_t i = 0; i < scalars.size (); ++i)
      names += (i == 0 ? "" : i + 1 == scalars.size () ? " and " : ", ") + scalars[i].name;
    add ((scalars.size () == 1 ? "field " : "fields ") + names);
  }
  return text;
}

PointAttributes
attributesOf (const pcl::PCLPointCloud2& cloud)
{
  const auto find = [&] (const std::string& name) -> const pcl::PCLPointField* {
    for (const pcl::PCLPointField& f : cloud.fields)
      if (f.name == name)
        return &f;
    return nullptr;
  };
  PointAttributes out;
  const PointColours colours = readColours (cloud);
  out.colours = colours.rgba;
  out.alpha = colours.alpha;
  const pcl::PCLPointField* normal[3] = {find ("normal_x"), find ("normal_y"), find ("normal_z")};
  const bool has_normals = normal[0] && normal[1] && normal[2];
  if (has_normals)
    for (int k = 0; k < 3; ++k)
    {
      const std::vector<double> values = readFieldValues (cloud, *normal[k]);
      out.normals.resize (values.size ());
      for (std::size_t i = 0; i < values.size (); ++i)
        out.normals[i][k] = static_cast<float> (values[i]);
    }
  bool colour_field_taken = false;
  for (const pcl::PCLPointField& field : cloud.fields)
  {
    const std::string& name = field.name;
    if (name == "x" || name == "y" || name == "z" || name == "_" || name.empty () ||
        (has_normals && name.rfind ("normal_", 0) == 0 && name.size () == 8))
      continue;
    // The field readColours() took; a second colour field is kept as numbers.
    if ((name == "rgb" || name == "rgba") && !colour_field_taken && pcl::getFieldSize (field.datatype) == 4)
    {
      colour_field_taken = true;
      continue;
    }
    if (field.datatype < pcl::PCLPointField::INT8 || field.datatype > pcl::PCLPointField::FLOAT64)
      continue; // not a number: nothing a mesh vertex could carry
    const std::uint32_t count = std::max<std::uint32_t> (field.count, 1);
    for (std::uint32_t element = 0; element < count; ++element)
      out.scalars.push_back ({count == 1 ? name : name + "_" + std::to_string (element), field.datatype,
                              readFieldValues (cloud, field, element)});
  }
  return out;
}

} // namespace pcl_wrap::apps
