/* -*- c++ -*- ----------------------------------------------------------
   PERIDEM: the force store of the bond loops of bond_style peridem and
   peridem/lps.

   LAMMPS lists the bonds of one atom i1 one after the other: the forces
   on i1 are summed in registers and stored once per atom, so that
   consecutive bonds do not wait for each other's store to f[i1] (with a
   cached 1/r0: 5.9 -> 5.0 ns per bond on in.peri.pmb). f is indexed flat
   from f[0], as LAMMPS's OPT styles do.
------------------------------------------------------------------------- */

#ifndef LMP_PERIDEM_BOND_LOOP_H
#define LMP_PERIDEM_BOND_LOOP_H

namespace PERIDEM {

class BondForceStore {
 public:
  explicit BondForceStore(double *f) : f(f) {}
  ~BondForceStore() { flush(); }

  // fbond (times x1 - x2) on i1, minus it on i2 when i2's force is kept here
  inline void add(int i1, int i2, bool to_i2, double delx, double dely, double delz, double fbond)
  {
    if (i1 != current) {
      flush();
      current = i1;
    }
    sum[0] += delx * fbond;
    sum[1] += dely * fbond;
    sum[2] += delz * fbond;
    if (to_i2) {
      double *f2 = f + 3 * i2;
      f2[0] -= delx * fbond;
      f2[1] -= dely * fbond;
      f2[2] -= delz * fbond;
    }
  }

  inline void flush()
  {
    if (current < 0) return;
    double *fc = f + 3 * current;
    fc[0] += sum[0];
    fc[1] += sum[1];
    fc[2] += sum[2];
    sum[0] = sum[1] = sum[2] = 0.0;
    current = -1;
  }

 private:
  double *f;
  int current = -1;
  double sum[3] = {0.0, 0.0, 0.0};
};

} // namespace PERIDEM

#endif
