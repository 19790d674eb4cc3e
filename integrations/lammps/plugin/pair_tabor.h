/* pair_style tabor: tabor's normal contact laws (Hertz, JKR with the fixed-grip or
   load-controlled separation, Maugis-Dugdale at any Tabor parameter, optional
   Kuwabara-Kono damping) with the friction, rolling and twisting models of LAMMPS's
   pair_style granular (tabor-tangential), through the tabor-ffi C ABI.

   One law per pair of atom types serves every effective radius (the branch is
   tabulated in normalized variables; crates/tabor-ffi), so any polydispersity is
   allowed. A type pair without a pair_coeff line of its own is mixed from the
   material forms of its two types, as pair granular mixes (tabor_mix_coeff).
   Works with newton on and off (it requests a newton-off neighbor list
   and keeps each contact's history on both atoms). Contact history is written to
   restart files. single() serves compute pair/local. */
#ifndef TABOR_PAIR_TABOR_H
#define TABOR_PAIR_TABOR_H

#include "pair.h"
#include "tabor_coeff.h"
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
  double single(int, int, int, int, double, double, double, double &) override;
  double memory_usage() override;

 private:
  struct Coeff {
    int set = 0;      // given by a pair_coeff line
    int mixed = 0;    // mixed at init from the I I and J J material forms
    TaborCoeff given;    // as parsed (its material, for mixing)
    TaborLawParams params{};
    TaborFrictionParams friction{};
    TaborContact *contact = nullptr;    // serves every effective radius
    double reach = 0.0;                 // interaction range at the largest R* of the types
  };
  std::vector<Coeff> coeffs;    // (ntypes+1)^2, upper triangle used
  double *maxrad;
  std::vector<double> minrad;    // smallest radius per type (per-contact Lambda range)
  class FixTaborHistory *fix_history;
  int history_width;

  int ntypes_alloc = 0;
  Coeff &coeff_of(int i, int j) { return coeffs[MIN(i, j) * (ntypes_alloc + 1) + MAX(i, j)]; }
  void free_laws();
  void mix(int i, int j);
  int evaluate(int i, int j, int update_history, TaborContactForces &out, int &first);
  [[noreturn]] void fail_all(int status, const char *what);
  [[noreturn]] void fail_one(int status, const char *what);
};

}    // namespace LAMMPS_NS

#endif
