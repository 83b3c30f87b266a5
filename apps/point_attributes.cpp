// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_attributes.h"

#include <pcl_wrap/point_field.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

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
  const std::size_t n = std::size_t (cloud.width) * cloud.height;
  if (n * cloud.point_step > cloud.data.size ())
    throw std::invalid_argument ("point data shorter than its header says");
  const auto checked = [&] (const pcl::PCLPointField& f, std::uint32_t element) {
    const std::size_t size = pcl::getFieldSize (f.datatype);
    if (size == 0 || f.offset + (element + 1) * size > cloud.point_step)
      throw std::invalid_argument ("field " + f.name + " beyond the point size");
    pcl::PCLPointField one = f;
    one.offset = static_cast<std::uint32_t> (f.offset + element * size);
    return one;
  };
  const auto find = [&] (const std::string& name) -> const pcl::PCLPointField* {
    for (const pcl::PCLPointField& f : cloud.fields)
      if (f.name == name)
        return &f;
    return nullptr;
  };
  PointAttributes out;
  const pcl::PCLPointField* normal[3] = {find ("normal_x"), find ("normal_y"), find ("normal_z")};
  const bool has_normals = normal[0] && normal[1] && normal[2];
  if (has_normals)
  {
    out.normals.resize (n);
    for (int k = 0; k < 3; ++k)
    {
      const pcl::PCLPointField f = checked (*normal[k], 0);
      for (std::size_t i = 0; i < n; ++i)
        out.normals[i][k] = static_cast<float> (readPointField (&cloud.data[i * cloud.point_step], f));
    }
  }
  for (const pcl::PCLPointField& field : cloud.fields)
  {
    const std::string& name = field.name;
    if (name == "x" || name == "y" || name == "z" || name == "_" || name.empty () ||
        (has_normals && name.rfind ("normal_", 0) == 0 && name.size () == 8))
      continue;
    if ((name == "rgb" || name == "rgba") && out.colours.empty () && pcl::getFieldSize (field.datatype) == 4)
    {
      const pcl::PCLPointField f = checked (field, 0);
      out.alpha = name == "rgba";
      out.colours.resize (n);
      for (std::size_t i = 0; i < n; ++i)
      {
        std::uint32_t packed; // 0xAARRGGBB, whether the field is a float or an integer
        std::memcpy (&packed, &cloud.data[i * cloud.point_step + f.offset], 4);
        out.colours[i] = {std::uint8_t (packed >> 16), std::uint8_t (packed >> 8), std::uint8_t (packed),
                          out.alpha ? std::uint8_t (packed >> 24) : std::uint8_t (255)};
      }
      continue;
    }
    if (field.datatype < pcl::PCLPointField::INT8 || field.datatype > pcl::PCLPointField::FLOAT64)
      continue; // not a number: nothing a mesh vertex could carry
    const std::uint32_t count = std::max<std::uint32_t> (field.count, 1);
    for (std::uint32_t element = 0; element < count; ++element)
    {
      const pcl::PCLPointField f = checked (field, element);
      ScalarField& scalar = out.scalars.emplace_back (
          ScalarField{count == 1 ? name : name + "_" + std::to_string (element), field.datatype, {}});
      scalar.values.resize (n);
      for (std::size_t i = 0; i < n; ++i)
        scalar.values[i] = readPointField (&cloud.data[i * cloud.point_step], f);
    }
  }
  return out;
}

} // namespace pcl_wrap::apps
