// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_input.h"

#include "message_exchange.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace pcl_wrap::mpi
{
namespace
{

namespace fs = std::filesystem;

bool
isPointFile (const fs::path& path)
{
  const std::string ext = path.extension ().string ();
  return ext == ".xyz" || ext == ".txt" || ext == ".pcd" || ext == ".ply" || ext == ".off" || ext == ".obj";
}

} // namespace

std::vector<std::string>
InputSource::files () const
{
  std::error_code error;
  if (!fs::exists (path, error))
    throw apps::FileError (path + ": no such file or folder");
  if (!fs::is_directory (path))
    return {path};
  std::vector<std::string> out;
  for (const fs::directory_entry& entry : fs::directory_iterator (path))
    if (entry.is_regular_file () && isPointFile (entry.path ()))
      out.push_back (entry.path ().string ());
  std::sort (out.begin (), out.end ());
  if (out.empty ())
    throw apps::FileError (path + ": a folder with no point file (.xyz, .txt, .pcd, .ply, .off, .obj)");
  return out;
}

apps::PointFile
InputSource::readAll () const
{
  const std::vector<std::string> paths = files ();
  if (paths.size () == 1)
    return apps::readPointFile (paths[0], weight_field, weights_column);
  apps::PointFile all;
  for (const std::string& file : paths)
  {
    apps::PointFile part = apps::readPointFile (file, weight_field, weights_column);
    if (!part.weights.empty () && all.weights.size () != all.points.size ())
      throw apps::FileError (file + ": weights where earlier files have none");
    all.points.insert (all.points.end (), part.points.begin (), part.points.end ());
    all.weights.insert (all.weights.end (), part.weights.begin (), part.weights.end ());
  }
  if (!all.weights.empty () && all.weights.size () != all.points.size ())
    throw apps::FileError (path + ": some files have weights and some not");
  return all;
}

InputShare
readShare (MPI_Comm comm, const InputSource& source)
{
  int ranks = 0, rank = 0;
  MPI_Comm_size (comm, &ranks);
  MPI_Comm_rank (comm, &rank);
  const std::vector<std::string> paths = source.files ();
  // Runs of files of about equal bytes; with one file, rank 0 has it.
  std::vector<std::uintmax_t> bytes (paths.size ());
  std::uintmax_t all_bytes = 0;
  for (std::size_t f = 0; f < paths.size (); ++f)
    all_bytes += bytes[f] = fs::file_size (paths[f]);
  std::vector<int> reader (paths.size ());
  std::uintmax_t before = 0;
  for (std::size_t f = 0; f < paths.size (); ++f)
  {
    reader[f] = all_bytes == 0 ? 0 : static_cast<int> ((before + bytes[f] / 2) * ranks / all_bytes);
    reader[f] = std::min (reader[f], ranks - 1);
    before += bytes[f];
  }
  // Each file's point count, for the indices of the concatenation.
  std::vector<std::uint64_t> counts (paths.size (), 0), mine (paths.size (), 0);
  std::vector<apps::PointFile> read (paths.size ());
  for (std::size_t f = 0; f < paths.size (); ++f)
    if (reader[f] == rank)
    {
      read[f] = apps::readPointFile (paths[f], source.weight_field, source.weights_column);
      mine[f] = read[f].points.size ();
    }
  MPI_Allreduce (mine.data (), counts.data (), static_cast<int> (counts.size ()), MPI_UINT64_T, MPI_SUM, comm);
  InputShare share;
  std::uint64_t first = 0;
  for (std::size_t f = 0; f < paths.size (); ++f)
  {
    if (reader[f] == rank)
    {
      const apps::PointFile& file = read[f];
      for (std::size_t i = 0; i < file.points.size (); ++i)
      {
        const Point3& p = file.points[i];
        const double w = file.weights.empty () ? 0.0 : file.weights[i];
        const auto index = static_cast<PointIndex> (first + i);
        if (std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]) && std::isfinite (w))
          share.points.push_back ({p, w, index, 0});
        else
          share.skipped.push_back (index);
      }
      read[f] = {};
    }
    first += counts[f];
  }
  if (first > std::uint64_t (~PointIndex (0)))
    throw apps::FileError (source.path + ": more than 2^32 - 1 points");
  share.total = first;
  return share;
}

} // namespace pcl_wrap::mpi
