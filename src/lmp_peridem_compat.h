/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM - peridynamic grains (PeriDEM) for LAMMPS

   Copyright (C) 2026 The PERIDEM developers.
   This software is distributed under the GNU General Public License,
   version 2; see the LICENSE file in the top-level PERIDEM directory.
   SPDX-License-Identifier: GPL-2.0-only
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   PERIDEM: the differences between LAMMPS versions, in one place.

   PERIDEM builds against LAMMPS 29 Sep 2021 (Debian bookworm) and 4 Feb 2025.
   Each difference is decided by what the LAMMPS at hand provides (a test of
   its API at compile time), not by a version number: LAMMPS defines no
   numeric version macro, and a feature test cannot leave a dead branch.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_COMPAT_H
#define LMP_PERIDEM_COMPAT_H

#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "modify.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "utils.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace PERIDEM_NS {

namespace compat_detail {
// LAMMPS 2022 and later: Neighbor::add_request(Pair *, int flags = 0) (chosen when it exists:
// the int argument matches better than long)
template <typename N, typename P>
auto request_half(N *neighbor, P *pair, int, int) -> decltype(neighbor->add_request(pair), void())
{
  neighbor->add_request(pair);
}
// LAMMPS 29 Sep 2021: Neighbor::request(void *requestor, int instance), half list by default
template <typename N, typename P> void request_half(N *neighbor, P *pair, int instance_me, long)
{
  neighbor->request(pair, instance_me);
}
template <typename R, typename C, typename A> A first_argument(R (C::*)(A));

// 2022 and later: Comm::forward_comm / reverse_comm overloaded on the style (Fix *, Compute *)
template <typename C, typename S>
auto forward(C *comm, S *style, int size, int) -> decltype(comm->forward_comm(style, size), void())
{
  comm->forward_comm(style, size);
}
template <typename C, typename S>
auto reverse(C *comm, S *style, int size, int) -> decltype(comm->reverse_comm(style, size), void())
{
  comm->reverse_comm(style, size);
}
template <typename C, typename F>
auto reverse_variable(C *comm, F *fix, int) -> decltype(comm->reverse_comm_variable(fix), void())
{
  comm->reverse_comm_variable(fix);
}
// 29 Sep 2021: one name per style kind (the compute versions take no size)
template <typename C> void forward(C *comm, LAMMPS_NS::Fix *fix, int size, long)
{
  comm->forward_comm_fix(fix, size);
}
template <typename C> void reverse(C *comm, LAMMPS_NS::Fix *fix, int size, long)
{
  comm->reverse_comm_fix(fix, size);
}
template <typename C> void forward(C *comm, LAMMPS_NS::Compute *compute, int, long)
{
  comm->forward_comm_compute(compute);
}
template <typename C> void reverse(C *comm, LAMMPS_NS::Compute *compute, int, long)
{
  comm->reverse_comm_compute(compute);
}
template <typename C> void reverse(C *comm, LAMMPS_NS::Pair *pair, int, long)
{
  comm->reverse_comm_pair(pair);
}
template <typename C, typename F> void reverse_variable(C *comm, F *fix, long)
{
  comm->reverse_comm_fix_variable(fix);
}

// 2022 and later: Domain::get_region_by_id; 29 Sep 2021: an index into Domain::regions
template <typename D>
auto region(D *domain, const std::string &id, int) -> decltype(domain->get_region_by_id(id))
{
  return domain->get_region_by_id(id);
}
template <typename D> LAMMPS_NS::Region *region(D *domain, const std::string &id, long)
{
  const int i = domain->find_region(id);
  return i < 0 ? nullptr : domain->regions[i];
}

// 2022 and later: Modify::get_fix_by_style (a list); 29 Sep 2021: find_fix_by_style (an index)
template <typename M>
auto has_fix_style(M *modify, const std::string &style, int)
    -> decltype(modify->get_fix_by_style(style), bool())
{
  return !modify->get_fix_by_style(style).empty();
}
template <typename M> bool has_fix_style(M *modify, const std::string &style, long)
{
  return modify->find_fix_by_style(style.c_str()) >= 0;
}
} // namespace compat_detail

// Forward (owned -> ghost) and reverse (ghost -> owner) communication of a fix, compute or pair
// through its pack/unpack functions.
inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix, int size = 0)
{
  compat_detail::forward(comm, fix, size, 0);
}
inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix, int size = 0)
{
  compat_detail::reverse(comm, fix, size, 0);
}
inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Compute *compute)
{
  compat_detail::forward(comm, compute, 0, 0);
}
inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Compute *compute)
{
  compat_detail::reverse(comm, compute, 0, 0);
}
inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Pair *pair)
{
  compat_detail::reverse(comm, pair, 0, 0);
}
// reverse communication with a per-atom size (Fix::pack_reverse_comm_size)
inline void reverse_comm_variable(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
{
  compat_detail::reverse_variable(comm, fix, 0);
}

// The region with this ID, nullptr if there is none.
inline LAMMPS_NS::Region *find_region(LAMMPS_NS::Domain *domain, const std::string &id)
{
  return compat_detail::region(domain, id, 0);
}

// Whether a fix whose style matches `style` (LAMMPS's regex: "^peridem/wall") exists.
inline bool has_fix_style(LAMMPS_NS::Modify *modify, const std::string &style)
{
  return compat_detail::has_fix_style(modify, style, 0);
}

// The name argument of AtomVec::property_atom(): char * (29 Sep 2021) or
// const std::string & (2022 and later), taken from the LAMMPS at hand.
using PropertyAtomName =
    decltype(compat_detail::first_argument(&LAMMPS_NS::AtomVec::property_atom));

// The per-atom field lists of an atom style (AtomVec::fields_grow, ...): a
// space-separated char * (29 Sep 2021) or a std::vector<std::string> (2022 and
// later); the overload is chosen by the type the LAMMPS at hand declares.
inline void set_fields(char *&field, const char *names)
{
  field = const_cast<char *>(names);
}
inline void set_fields(std::vector<std::string> &field, const char *names)
{
  field = LAMMPS_NS::utils::split_words(names);
}

// A default (half, newton-dependent) neighbour list for a pair style.
template <typename PairT>
void request_half_neighbor_list(LAMMPS_NS::Neighbor *neighbor, PairT *pair, int instance_me)
{
  compat_detail::request_half(neighbor, pair, instance_me, 0);
}

} // namespace PERIDEM_NS
} // namespace LAMMPS_NS

#endif
