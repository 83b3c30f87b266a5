// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "ply_ascii.h"

#include <pcl/common/io.h>

#include <limits>
#include <map>
#include <sstream>
#include <string>

namespace pcl_wrap::apps
{
namespace
{

/** Appends a field as PCL's reader does: at the end of the point. */
void
appendField (pcl::PCLPointCloud2& cloud, const std::string& name, std::uint8_t type)
{
  pcl::PCLPointField field;
  field.name = name;
  field.offset = cloud.point_step;
  field.datatype = type;
  field.count = 1;
  cloud.fields.push_back (field);
  cloud.point_step += static_cast<std::uint32_t> (pcl::getFieldSize (type));
}

} // namespace

std::uint8_t
plyFieldType (const std::string& type)
{
  static const std::map<std::string, std::uint8_t> TYPES = {
      {"char", pcl::PCLPointField::INT8},      {"int8", pcl::PCLPointField::INT8},
      {"uchar", pcl::PCLPointField::UINT8},    {"uint8", pcl::PCLPointField::UINT8},
      {"short", pcl::PCLPointField::INT16},    {"int16", pcl::PCLPointField::INT16},
      {"ushort", pcl::PCLPointField::UINT16},  {"uint16", pcl::PCLPointField::UINT16},
      {"int", pcl::PCLPointField::INT32},      {"int32", pcl::PCLPointField::INT32},
      {"uint", pcl::PCLPointField::UINT32},    {"uint32", pcl::PCLPointField::UINT32},
      {"float", pcl::PCLPointField::FLOAT32},  {"float32", pcl::PCLPointField::FLOAT32},
      {"double", pcl::PCLPointField::FLOAT64}, {"float64", pcl::PCLPointField::FLOAT64}};
  const auto found = TYPES.find (type);
  return found == TYPES.end () ? 0 : found->second;
}

std::optional<PlyVertexLayout>
plainAsciiPlyLayout (std::istream& in)
{
  std::string line;
  if (!std::getline (in, line) || line != "ply")
    return std::nullopt;
  PlyVertexLayout out;
  pcl::PCLPointCloud2& cloud = out.cloud;
  bool ascii = false, ended = false, in_vertex = false;
  int elements = 0;
  std::uint64_t vertices = 0;
  // Colours: how many of red, green, blue and alpha came so far, in that order and in a row.
  int colour = 0;
  std::uint32_t rgb_at = 0;
  while (!ended && std::getline (in, line))
  {
    if (line.find ('\r') != std::string::npos)
      return std::nullopt;
    std::istringstream words (line);
    std::string keyword, name, type;
    words >> keyword;
    if (keyword == "end_header")
      ended = !(words >> name);
    else if (keyword == "format")
    {
      words >> type >> name;
      ascii = type == "ascii" && name == "1.0";
    }
    else if (keyword == "element")
    {
      std::uint64_t count = 0;
      if (!(words >> name >> count))
        return std::nullopt;
      in_vertex = ++elements == 1;
      if (in_vertex ? name != "vertex" : name == "vertex" || name == "camera" || name == "range_grid")
        return std::nullopt;
      if (in_vertex)
        vertices = count;
    }
    else if (keyword == "property" && !in_vertex)
      continue; // another element's: its lines need only be numbers
    else if (keyword == "property")
    {
      words >> type >> name;
      const std::uint8_t field_type = plyFieldType (type);
      if (field_type == 0 || name.empty ())
        return std::nullopt; // a list, or no name
      const bool byte = field_type == pcl::PCLPointField::UINT8;
      const int component = !byte             ? 0
                            : name == "red"   ? 1
                            : name == "green" ? 2
                            : name == "blue"  ? 3
                            : name == "alpha" ? 4
                                              : 0;
      if (component != 0 ? component != colour + 1 : colour == 1 || colour == 2)
        return std::nullopt; // colours out of order, or apart
      if (byte && name.compare (0, 8, "diffuse_") == 0)
        return std::nullopt;
      if (component == 1)
      {
        rgb_at = cloud.point_step;
        appendField (cloud, "rgb", pcl::PCLPointField::FLOAT32);
      }
      if (component == 4)
      {
        cloud.fields.back ().name = "rgba";
        cloud.fields.back ().datatype = pcl::PCLPointField::UINT32;
      }
      if (component != 0)
      {
        // The packed word's bytes, little end first: blue, green, red, alpha.
        static const std::uint32_t BYTE[] = {0, 2, 1, 0, 3};
        out.values.push_back ({name, field_type, field_type, rgb_at + BYTE[component]});
        colour = component;
        continue;
      }
      const bool intensity = byte && name == "intensity";
      const std::uint8_t stored = intensity ? std::uint8_t (pcl::PCLPointField::FLOAT32) : field_type;
      out.values.push_back ({name, field_type, stored, cloud.point_step});
      appendField (cloud, name, stored);
    }
    else if (keyword != "comment" && keyword != "obj_info")
      return std::nullopt; // what PCL's reader is to judge
  }
  if (!ended || !ascii || elements == 0 || colour == 1 || colour == 2 || !in)
    return std::nullopt;
  for (pcl::PCLPointField& field : cloud.fields)
    if (field.name == "nx" || field.name == "ny" || field.name == "nz")
      field.name = std::string ("normal_") + field.name[1];
  if (cloud.point_step == 0 || vertices > std::numeric_limits<std::uint32_t>::max () ||
      vertices > std::numeric_limits<std::size_t>::max () / cloud.point_step)
    return std::nullopt;
  cloud.width = static_cast<std::uint32_t> (vertices);
  cloud.height = 1;
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.data.resize (std::size_t (cloud.point_step) * cloud.width);
  out.data_start = static_cast<std::uint64_t> (in.tellg ());
  return out;
}

} // namespace pcl_wrap::apps
