/* The contact coefficients `MODEL ARGS [KEYWORDS]` that pair_coeff of pair_style tabor
   and fix wall/tabor (and wall/tabor/region) take, parsed in one place so that both
   accept exactly the same models and keywords: a keyword added here works in both.

   MODEL ARGS: hertz E* | jkr/fixed-grip E* w | jkr/load-controlled E* w |
               maugis E* w Lambda
               or LAMMPS's material form: material E nu gamma MODEL [Lambda]
               (Young's modulus, Poisson's ratio, surface energy per surface;
               E* and w = 2 gamma follow as pair granular computes them)
   KEYWORDS:   poisson nu
               damping A | damping viscoelastic eta_n0 | damping tsuji e |
               damping coeff_restitution e
               tangential TMODEL k_t|NULL x_gamma mu
                 (TMODEL linear_history, mindlin, mindlin_rescale, mindlin_deresiewicz)
               rolling sds k_roll gamma_roll mu_roll
               twisting marshall | twisting sds k_tw gamma_tw mu_tw
               wall_material E_w nu_w gamma_w (walls, material form only)
   The meaning of each value is in doc/pair_tabor.rst. Every error is error->all,
   naming the command, the parameter and the value. */
#ifndef TABOR_TABOR_COEFF_H
#define TABOR_TABOR_COEFF_H

#include "comm.h"
#include "error.h"
#include "fmt/format.h"
#include "lammps.h"
#include "tabor_ffi.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class LAMMPS;

// One body's material in LAMMPS's form (pair granular's jkr E eta nu gamma):
// Young's modulus, Poisson's ratio, surface energy per surface.
struct TaborMaterial {
  double youngs = 0.0, poisson = 0.0, gamma = 0.0;
};

// One contact model's parameters, as tabor_contact_new takes them, and how they
// were given (the material form can be mixed across types, see tabor_mix_coeff).
struct TaborCoeff {
  TaborLawParams params{};
  TaborFrictionParams friction{};
  bool material = false;          // given as `material E nu gamma MODEL ...`
  TaborMaterial mat;              // its material (both bodies of it)
  bool stiffness_null = false;    // tangential k_t given as NULL (8 G* of the materials)
};

// pair granular's mixing of two materials (LAMMPS's GranSubMod::mix_stiffnessE):
// E* = 1 / ((1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j).
double tabor_mix_modulus(const TaborMaterial &a, const TaborMaterial &b);
// The effective shear modulus as pair granular's documentation gives it (and its
// mix_stiffnessG computes): G* = 1 / (2 (2 - nu_i)(1 + nu_i)/E_i + 2 (2 - nu_j)(1 + nu_j)/E_j).
double tabor_mix_shear(const TaborMaterial &a, const TaborMaterial &b);

/* The coefficients of types I J from those of I I and J J, both in the material
   form, mixed as pair granular mixes them: E* from both materials
   (tabor_mix_modulus), gamma and every other coefficient by the geometric mean
   sqrt(c_i c_j), k_t NULL (if either is) as 8 G* (tabor_mix_shear). The models,
   damping, tangential, rolling and twisting models and the maugis form must be
   the same. Returns "" or why the two cannot be mixed. */
std::string tabor_mix_coeff(const TaborCoeff &a, const TaborCoeff &b, TaborCoeff &out);

/* Parses `MODEL ARGS [KEYWORDS]` from arg[first] on. The keyword loop stops at
   the end of the arguments or at the first word listed in `stop` (the wall fix's
   wallstyles); returns the index of the first argument not consumed. `who` names
   the command in error messages ("pair tabor", "fix wall/tabor"). The parameters
   are checked by building one contact model (tabor_contact_new), so a value the
   library refuses is reported here with the library's message. */
int tabor_parse_coeff(LAMMPS *lmp, const std::string &who, int narg, char **arg, int first,
                      const std::vector<std::string> &stop, TaborCoeff &out);

// "" if a contact model's friction answers finitely on the scale at which
// tabor_contact_new checks its normal law (R* = 1 m), else why not (naming the
// friction parameters). Every rank alike (no communication).
std::string tabor_probe_contact(TaborContact *contact, const TaborFrictionParams &fr);

// An error met by one rank during a run (a contact step that fails): error->all
// when the run has one rank (a clean `ERROR:` line, the instance usable after
// it), error->one (an abort, the only safe way out of one rank) with more.
template <typename... Args>
[[noreturn]] void tabor_fail_rank(LAMMPS *lmp, const std::string &file, int line, const std::string &format,
                                  Args &&...args)
{
  std::string text = fmt::format(format, std::forward<Args>(args)...);
  if (lmp->comm->nprocs == 1) lmp->error->all(file, line, text);
  lmp->error->one(file, line, text);
  throw;    // not reached
}

// error->all with the library's last error message, `what` and the status.
[[noreturn]] void tabor_fail_all(LAMMPS *lmp, const std::string &who, int status, const char *what);

// A message some ranks hold (a restart record refused where its atom lives; empty
// elsewhere) as one error->all on every rank, with the message of the lowest rank
// that has one; returns when no rank has one. Collective.
void tabor_raise_first(LAMMPS *lmp, const std::string &message);

/* The offset of fix number `nth`'s record in atom `nlocal`'s per-atom restart
   data (atom->extra), walking the records before it by their lengths, each
   checked (a whole number >= 1 that stays inside the atom's data): -1 and
   `problem` set when one is corrupted. */
int tabor_restart_offset(LAMMPS *lmp, int nlocal, int nth, std::string &problem);

/* Why the `width` stored doubles of a contact history cannot be handed to
   tabor_contact_step ("" if they can): tabor-ffi's own rules (the contact flag
   0 or 1, every value finite, and in a whole micro-slip history of
   TABOR_CONTACT_HISTORY_LEN doubles the bed's spacing and last squared contact
   radius >= 0 and the radius inside the bed). */
std::string tabor_history_problem(const double *h, int width);

/* Whether a stored contact history of `stored` doubles can be kept in `kept`:
   TABOR_HISTORY_FITS when every double beyond the kept ones is zero (a contact
   that did not use them; fewer doubles start the rest at zero),
   TABOR_HISTORY_THORNTON for a 16-double history with a value beyond the 10th
   (Thornton's incremental micro-slip state of builds before the spring bed,
   which this build cannot continue), TABOR_HISTORY_DROPPED for another value
   that would be dropped (a micro-slip bed the model cannot continue, or a newer
   tabor's state). The rule of fix tabor/history and fix wall/tabor. */
enum TaborHistoryFit { TABOR_HISTORY_FITS, TABOR_HISTORY_THORNTON, TABOR_HISTORY_DROPPED };
TaborHistoryFit tabor_history_fit(const double *h, int stored, int kept);

/* The atoms a contact law will see, checked before a run: type in 1..ntypes,
   a finite radius > 0 and mass > 0, finite position, velocity and spin. The
   first bad atom (lowest ID) of `groupbit` stops the run on every rank
   (error->all) with `who`, its ID, type and what is wrong. Collective. */
void tabor_check_atoms(LAMMPS *lmp, const std::string &who, int groupbit);

}    // namespace LAMMPS_NS

#endif
