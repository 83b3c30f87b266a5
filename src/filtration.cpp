// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// X(delta) and W(delta) of the wrap filtration, by a filter over the values.
#include "filtration_data.h"

#include "wrap/boundary.h"
#include "wrap/subcomplex.h"

#include <stdexcept>

namespace pcl_wrap
{
namespace
{

const Filtration::Data&
dataOf (const std::shared_ptr<const Filtration::Data>& data)
{
  if (!data)
    throw std::logic_error ("Filtration: not computed (set WrapParameters::filtration)");
  return *data;
}

/** Membership in X(delta): removed only by the deletion of a sink larger than delta. */
std::array<std::vector<std::uint8_t>, 4>
membership (const Filtration::Data& d, double delta)
{
  std::array<std::vector<std::uint8_t>, 4> in_x;
  for (int k = 0; k <= 3; ++k)
  {
    in_x[k].resize (d.filtration->value[k].size ());
    for (detail::SimplexId s = 0; s < in_x[k].size (); ++s)
      in_x[k][s] = d.filtration->inX ({k, s}, delta);
  }
  return in_x;
}

} // namespace

const std::vector<double>&
Filtration::sinkSizes () const
{
  return dataOf (data_).filtration->sink_sizes;
}

std::array<std::size_t, 4>
Filtration::xSize (double delta) const
{
  const Data& d = dataOf (data_);
  const auto in_x = membership (d, delta);
  std::array<std::size_t, 4> size{};
  for (int k = 0; k <= 3; ++k)
    for (std::uint8_t in : in_x[k])
      size[k] += in;
  return size;
}

WrapSurface
Filtration::surface (double delta) const
{
  const Data& d = dataOf (data_);
  const detail::Subcomplex x (*d.complex, membership (d, delta));
  return d.input_indices.surface (
      detail::extractBoundary (*d.complex, x, true, [&] (std::uint32_t v) { return d.input_indices (v); }));
}

Filtration
Filtration::reindexed (const std::function<std::uint32_t (std::uint32_t)>& index) const
{
  auto data = std::make_shared<Data> (dataOf (data_));
  data->input_indices = data->input_indices.reindexed (index);
  return Filtration (std::move (data));
}

} // namespace pcl_wrap
