/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: the differences between LAMMPS versions, in one place.

   PERIDEM is built against LAMMPS 29 Sep 2021 (Debian bookworm). Newer
   LAMMPS renamed some APIs; the styles call these helpers instead.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_COMPAT_H
#define LMP_PERIDEM_COMPAT_H

#include "neighbor.h"
#include "version.h"

#if __has_include("neigh_request.h")
#include "neigh_request.h"
#endif

namespace PERIDEM {

// A default (half, newton-dependent) neighbour list for a pair style.
// 29 Sep 2021: neighbor->request(this, instance_me);
// 2022 and later: neighbor->add_request(this).
template <typename PairT>
void request_half_neighbor_list(LAMMPS_NS::Neighbor *neighbor, PairT *pair, int instance_me)
{
#if defined(LAMMPS_VERSION_NUMBER) && LAMMPS_VERSION_NUMBER >= 20220324
  (void)instance_me;
  neighbor->add_request(pair);
#else
  neighbor->request(pair, instance_me);
#endif
}

} // namespace PERIDEM

#endif
