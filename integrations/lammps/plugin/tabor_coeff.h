/* The contact coefficients `MODEL ARGS [KEYWORDS]` that pair_coeff of pair_style tabor
   and fix wall/tabor (and wall/tabor/region) take, parsed in one place so that both
   accept exactly the same models and keywords: a keyword added here works in both.

   MODEL ARGS: hertz E* | jkr/fixed-grip E* w | jkr/load-controlled E* w |
               maugis E* w Lambda
   KEYWORDS:   poisson nu
               damping A | damping viscoelastic eta_n0 | damping tsuji e |
               damping coeff_restitution e
               tangential TMODEL k_t|NULL x_gamma mu
                 (TMODEL linear_history, mindlin, mindlin_rescale, mindlin_deresiewicz)
               rolling sds k_roll gamma_roll mu_roll
               twisting marshall | twisting sds k_tw gamma_tw mu_tw
   The meaning of each value is in doc/pair_tabor.rst. Every error is error->all,
   naming the command, the parameter and the value. */
#ifndef TABOR_TABOR_COEFF_H
#define TABOR_TABOR_COEFF_H

#include "tabor_ffi.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class LAMMPS;

// One contact model's parameters, as tabor_contact_new takes them.
struct TaborCoeff {
  TaborLawParams params{};
  TaborFrictionParams friction{};
};

/* Parses `MODEL ARGS [KEYWORDS]` from arg[first] on. The keyword loop stops at
   the end of the arguments or at the first word listed in `stop` (the wall fix's
   wallstyles); returns the index of the first argument not consumed. `who` names
   the command in error messages ("pair tabor", "fix wall/tabor"). The parameters
   are checked by building one contact model (tabor_contact_new), so a value the
   library refuses is reported here with the library's message. */
int tabor_parse_coeff(LAMMPS *lmp, const std::string &who, int narg, char **arg, int first,
                      const std::vector<std::string> &stop, TaborCoeff &out);

// error->all with the library's last error message, `what` and the status.
[[noreturn]] void tabor_fail_all(LAMMPS *lmp, const std::string &who, int status, const char *what);

// A message some ranks hold (a restart record refused where its atom lives; empty
// elsewhere) as one error->all on every rank, with the message of the lowest rank
// that has one; returns when no rank has one. Collective.
void tabor_raise_first(LAMMPS *lmp, const std::string &message);

}    // namespace LAMMPS_NS

#endif
