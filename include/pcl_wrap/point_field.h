// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace pcl_wrap
{

/** \brief The first value of a numeric point field, as a double.
  * \param[in] point the start of the point's bytes
  * \param[in] field the field (its offset and datatype)
  * \throws std::invalid_argument when the field is not numeric */
inline double
readPointField (const std::uint8_t* point, const pcl::PCLPointField& field)
{
  const std::uint8_t* at = point + field.offset;
  const auto as = [at] (auto value) {
    std::memcpy (&value, at, sizeof (value));
    return double (value);
  };
  switch (field.datatype)
  {
  case pcl::PCLPointField::INT8: return as (std::int8_t ());
  case pcl::PCLPointField::UINT8: return as (std::uint8_t ());
  case pcl::PCLPointField::INT16: return as (std::int16_t ());
  case pcl::PCLPointField::UINT16: return as (std::uint16_t ());
  case pcl::PCLPointField::INT32: return as (std::int32_t ());
  case pcl::PCLPointField::UINT32: return as (std::uint32_t ());
  case pcl::PCLPointField::FLOAT32: return as (float ());
  case pcl::PCLPointField::FLOAT64: return as (double ());
  default: throw std::invalid_argument ("the field '" + field.name + "' is not numeric");
  }
}

/** \brief The first value of the numeric field \a name of every point of \a cloud, as doubles;
  * checked first, so that a malformed cloud (a message, a file) is never read out of bounds.
  * \throws std::invalid_argument when the field is missing or not numeric, lies beyond the point
  *         size, or the data is shorter than width x height points */
inline std::vector<double>
readFieldValues (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  const auto field = std::find_if (cloud.fields.begin (), cloud.fields.end (),
                                   [&] (const pcl::PCLPointField& f) { return f.name == name; });
  if (field == cloud.fields.end () || field->datatype < pcl::PCLPointField::INT8 ||
      field->datatype > pcl::PCLPointField::FLOAT64)
    throw std::invalid_argument ("no numeric field '" + name + "'");
  if (field->offset + pcl::getFieldSize (field->datatype) > cloud.point_step)
    throw std::invalid_argument ("field " + name + " beyond the point size");
  const std::size_t n = std::size_t (cloud.width) * cloud.height;
  if (n * cloud.point_step > cloud.data.size ())
    throw std::invalid_argument ("point data shorter than its header says");
  std::vector<double> values (n);
  for (std::size_t i = 0; i < n; ++i)
    values[i] = readPointField (&cloud.data[i * cloud.point_step], *field);
  return values;
}

} // namespace pcl_wrap
