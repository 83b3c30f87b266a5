// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl/PCLPointCloud2.h>
#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <array>
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

/** \brief The number of points of \a cloud, width x height.
  * \throws std::invalid_argument when the data is shorter than that many points */
inline std::size_t
checkedPointCount (const pcl::PCLPointCloud2& cloud)
{
  const std::size_t n = std::size_t (cloud.width) * cloud.height;
  if (n * cloud.point_step > cloud.data.size ())
    throw std::invalid_argument ("point data shorter than its header says");
  return n;
}

/** \brief Element \a element of \a field as a field of its own (its offset moved to the element).
  * \throws std::invalid_argument when it lies beyond the point size of \a cloud */
inline pcl::PCLPointField
checkedFieldElement (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& field, std::uint32_t element = 0)
{
  const std::size_t size = pcl::getFieldSize (field.datatype);
  if (size == 0 || field.offset + (element + 1) * size > cloud.point_step)
    throw std::invalid_argument ("field " + field.name + " beyond the point size");
  pcl::PCLPointField one = field;
  one.offset = static_cast<std::uint32_t> (field.offset + element * size);
  return one;
}

/** \brief Element \a element of the numeric field \a field of every point of \a cloud, as
  * doubles; checked first, so that a malformed cloud (a message, a file) is never read out of
  * bounds.
  * \throws std::invalid_argument when the field is not numeric, lies beyond the point size, or
  *         the data is shorter than width x height points */
inline std::vector<double>
readFieldValues (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& field, std::uint32_t element = 0)
{
  if (field.datatype < pcl::PCLPointField::INT8 || field.datatype > pcl::PCLPointField::FLOAT64)
    throw std::invalid_argument ("the field '" + field.name + "' is not numeric");
  const pcl::PCLPointField one = checkedFieldElement (cloud, field, element);
  const std::size_t n = checkedPointCount (cloud);
  std::vector<double> values (n);
  for (std::size_t i = 0; i < n; ++i)
    values[i] = readPointField (&cloud.data[i * cloud.point_step], one);
  return values;
}

/** \brief The first value of the numeric field \a name of every point of \a cloud, as doubles;
  * checked as readFieldValues() above.
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
  return readFieldValues (cloud, *field);
}

/** \brief The colours of a cloud's points: red, green, blue and alpha per point. */
struct PointColours
{
  std::vector<std::array<std::uint8_t, 4>> rgba; ///< empty when the cloud has no colour field
  bool alpha = false;                            ///< whether the field gave the alpha (else 255)
};

/** \brief The colours of the points of \a cloud from its first packed "rgb" or "rgba" field
  * (0xAARRGGBB in 4 bytes, whether PCL typed it a float or an integer), checked as
  * readFieldValues().
  * \throws std::invalid_argument when the field lies beyond the point size or the data is short */
inline PointColours
readColours (const pcl::PCLPointCloud2& cloud)
{
  PointColours out;
  for (const pcl::PCLPointField& field : cloud.fields)
    if ((field.name == "rgb" || field.name == "rgba") && pcl::getFieldSize (field.datatype) == 4)
    {
      const pcl::PCLPointField f = checkedFieldElement (cloud, field);
      const std::size_t n = checkedPointCount (cloud);
      out.alpha = field.name == "rgba";
      out.rgba.resize (n);
      for (std::size_t i = 0; i < n; ++i)
      {
        std::uint32_t packed;
        std::memcpy (&packed, &cloud.data[i * cloud.point_step + f.offset], 4);
        out.rgba[i] = {std::uint8_t (packed >> 16), std::uint8_t (packed >> 8), std::uint8_t (packed),
                       out.alpha ? std::uint8_t (packed >> 24) : std::uint8_t (255)};
      }
      break;
    }
  return out;
}

} // namespace pcl_wrap
