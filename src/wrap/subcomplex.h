// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"
#include "util/portable.h"
#include "delaunay/simplicial_complex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief A subcomplex Y of Del S: which simplices are in it and, per simplex, how many of its
  * cofaces one dimension up are (docs/design.md §5). The retraction shrinks it to X; the
  * boundary, the surface stage and the report read it.
  *
  * Reads are relaxed atomic loads (plain loads on x86): the first retraction changes Y on several
  * threads. */
class Subcomplex
{
public:
  /** \brief All of Del S (omega is never counted as a coface), its coface counts counted. */
  explicit Subcomplex (const SimplicialComplex& complex);

  /** \brief All of Del S, taking over the counts of SimplicialComplex::releaseCofaceCounts(). */
  Subcomplex (const SimplicialComplex& complex, std::array<FilledInParallel<std::uint32_t>, 3> coface_counts);

  /** \brief The simplices for which \a members is true, which must form a subcomplex (e.g.
    * X(delta) of the wrap filtration, or a solid's closure). */
  Subcomplex (const SimplicialComplex& complex, const std::array<std::vector<std::uint8_t>, 4>& members);

  const SimplicialComplex& complex () const { return complex_; }

  bool contains (Simplex s) const { return relaxedLoad (&in_[s.dim][s.id]) != 0; }

  /** \brief The number of cofaces of \a s of dimension s.dim + 1 in Y. */
  std::uint32_t cofaceCount (Simplex s) const { return s.dim < 3 ? relaxedLoad (&counts_[s.dim][s.id]) : 0; }

  /** \brief In Y with no coface in Y (any coface contains one a dimension up). */
  bool principal (Simplex s) const { return contains (s) && cofaceCount (s) == 0; }

  /** \brief The number of k-simplices in Y. */
  std::size_t size (int k) const;

  /** \brief Takes \a s out of Y; its facets' counts are the caller's to lower (a collapse lowers
    * only those of the facets it keeps). CONCURRENT: other threads change other simplices. */
  template <bool CONCURRENT>
  void take (Simplex s)
  {
    if (CONCURRENT)
      relaxedStore (&in_[s.dim][s.id], std::uint8_t (0));
    else
      in_[s.dim][s.id] = 0;
  }

  /** \brief Takes \a s out of Y unless another thread did first; returns whether this one did. */
  bool takeFirst (Simplex s)
  {
    std::uint8_t in = 1;
    return relaxedCompareExchange (&in_[s.dim][s.id], in, std::uint8_t (0));
  }

  /** \brief One coface of \a s one dimension up left Y. */
  template <bool CONCURRENT>
  void loseCoface (Simplex s)
  {
    if (CONCURRENT)
      relaxedFetchSub (&counts_[s.dim][s.id], 1u);
    else
      --counts_[s.dim][s.id];
  }

  /** \brief Puts \a s back into Y, counting it in its facets' counts (its facets must be in Y). */
  void putBack (Simplex s);

private:
  void countCofaces ();

  const SimplicialComplex& complex_;
  std::array<FilledInParallel<std::uint8_t>, 4> in_;
  std::array<FilledInParallel<std::uint32_t>, 3> counts_; // per k-simplex: its (k+1)-cofaces in Y
};

} // namespace pcl_wrap::detail
