/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: pair_style peridem/contact, nonlocal node-to-node contact with
   damping and friction between grains and within a grain (self-contact).
   See doc/pair_peridem_contact.rst.
------------------------------------------------------------------------- */

#ifdef PAIR_CLASS
// clang-format off
PairStyle(peridem/contact,PairPeridemContact);
// clang-format on
#else

#ifndef LMP_PAIR_PERIDEM_CONTACT_H
#define LMP_PAIR_PERIDEM_CONTACT_H

#include "lmp_peridem_contact.h"
#include "pair.h"

#include <vector>

namespace LAMMPS_NS {

class PairPeridemContact : public Pair {
 public:
  PairPeridemContact(class LAMMPS *);
  ~PairPeridemContact() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;

 protected:
  // contact law of each type pair, index [i][j] with 1 <= i, j <= ntypes
  std::vector<std::vector<PERIDEM::ContactSpec>> spec;
  double **cut;      // contact radius of each type pair
  int self_contact;  // 1: nodes of one grain without an intact bond touch too
  double dissipated; // energy dissipated by damping and friction on this rank

  void allocate();
  void mix(int i, int j);
  void report_time_step();
};

} // namespace LAMMPS_NS

#endif
#endif
