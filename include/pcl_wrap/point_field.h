// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl/PCLPointField.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

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

} // namespace pcl_wrap
