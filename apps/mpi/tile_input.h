// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "star_completion.h"

#include "point_file.h"

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief The input of a run: one point file, or a folder of point files (.xyz, .txt, .pcd, .ply,
  * .off, .obj) read in the order of their names as if they were one file. Point i is the i-th
  * point of that concatenation, on every rank. */
struct InputSource
{
  std::string path;
  std::string weight_field;
  bool weights_column = false;

  /** \brief The files, in order: the path itself, or the point files in the folder. */
  std::vector<std::string> files () const;
  /** \brief Every point of every file, with weights and attributes (the attributes only when
    * there is one file). */
  apps::PointFile readAll () const;
};

/** \brief A rank's share of the input as read, before the points go to their tiles. */
struct InputShare
{
  std::vector<PointRecord> points; ///< finite, with their input index (tile not yet set)
  std::vector<PointIndex> skipped; ///< non-finite coordinate or weight, on this share
  std::uint64_t total = 0;         ///< points in the whole input, on every rank
};

/** \brief Reads this rank's share: of a folder, a run of whole files (about as many points each
  * way, by file size); of one file, rank 0 reads it all and the others nothing. */
InputShare
readShare (MPI_Comm comm, const InputSource& source);

} // namespace pcl_wrap::mpi
