/* pair_style tabor: tabor's normal contact laws (Hertz, JKR with the fixed-grip or
   load-controlled separation, Maugis-Dugdale at any Tabor parameter, optional
   Kuwabara-Kono damping) through the tabor-ffi C ABI. Normal forces only. */
#ifndef TABOR_PAIR_TABOR_H
#define TABOR_PAIR_TABOR_H

#include "pair.h"
#include "tabor_ffi.h"

#include <vector>

namespace LAMMPS_NS {

class PairTabor : public Pair {
 public:
  PairTabor(class LAMMPS *);
  ~PairTabor() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  double memory_usage() override;

 private:
  struct Law {
    double rstar;
    TaborLaw *law;
    TaborLawInfo info;
  };
  struct Coeff {
    int set = 0;
    TaborLawParams params{};
    std::vector<Law> laws;    // one per distinct effective radius
  };
  std::vector<Coeff> coeffs;    // (ntypes+1)^2
  double *maxrad;
  class FixTaborHistory *fix_history;
  bigint evaluations, overflow_reported;

  int ntypes_alloc = 0;
  Coeff &coeff_of(int i, int j) { return coeffs[i * (ntypes_alloc + 1) + j]; }
  const Law &law_for(int itype, int jtype, double rstar);
  void free_laws();
  void check(int status, const char *what);
};

}    // namespace LAMMPS_NS

#endif
