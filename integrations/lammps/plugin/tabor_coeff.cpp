#include "tabor_coeff.h"

#include "comm.h"
#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;

void LAMMPS_NS::tabor_fail_all(LAMMPS *lmp, const std::string &who, int status, const char *what)
{
  char buf[512];
  tabor_last_error(buf, sizeof(buf));
  lmp->error->all(FLERR, "{}: {} (status {}): {}", who, what, status, buf);
  throw;    // not reached: error->all does not return
}

/* pair_coeff I J MODEL PARAMETERS [poisson nu]
              [damping A | damping viscoelastic eta_n0 | damping tsuji e | damping coeff_restitution e]
              [tangential TMODEL k_t|NULL x_gamma mu] [rolling sds k_roll gamma_roll mu_roll]
              [twisting marshall | twisting sds k_tw gamma_tw mu_tw]
   MODEL PARAMETERS: hertz E* | jkr/fixed-grip E* w | jkr/load-controlled E* w |
   maugis E* w Lambda.
   E*: effective modulus (Pa), w: work of adhesion (J/m^2, = 2 gamma of LAMMPS jkr),
   Lambda: Tabor parameter (held fixed for every effective radius: the Dugdale
   range h = d_n(R*)/Lambda grows as R*^(1/3)), A: Kuwabara-Kono dissipative time
   (s); the normal damping coefficient the tangential x_gamma multiplies is 2 E* A a.
   damping viscoelastic|tsuji|coeff_restitution: pair granular's damping models
   (c = eta_n0 m* a, or alpha(e) sqrt(m* (4/3) E* a) with Tsuji's polynomial or
   alpha = -sqrt(5) ln e / sqrt(pi^2 + ln^2 e)), the value after the name; on every
   normal model, jkr/fixed-grip, jkr/load-controlled and maugis too (with a the law's own contact radius), where
   pair granular refuses tsuji and coeff_restitution; they act unclipped (the contact
   lasts until the law separates), as pair granular without limit_damping.
   tangential, rolling, twisting: the keywords and parameters of pair_style granular
   (TMODEL linear_history, mindlin, mindlin_rescale, and tabor's mindlin_deresiewicz:
   Mindlin-Deresiewicz micro-slip in Thornton (1991)'s incremental form, its turning
   points kept in the contact's history; k_t NULL for the Mindlin models
   means 8 G* with G* = E* (1 - nu) / (2 (2 - nu)), the value pair granular computes
   for two bodies of one material, which needs `poisson nu`).
   Every error is reported on all ranks (error->all). */
int LAMMPS_NS::tabor_parse_coeff(LAMMPS *lmp, const std::string &who, int narg, char **arg, int first,
                                 const std::vector<std::string> &stop, TaborCoeff &out)
{
  Error *error = lmp->error;
  TaborLawParams p{};
  TaborFrictionParams fr{};
  if (first >= narg) error->all(FLERR, "{}: missing the model (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", who);
  std::string model = arg[first];
  int iarg = first + 1;
  auto stops = [&](int k) { return std::find(stop.begin(), stop.end(), std::string(arg[k])) != stop.end(); };
  auto number = [&](const std::string &what) {
    if (iarg >= narg || stops(iarg)) error->all(FLERR, "{} {}: missing {}", who, model, what);
    return utils::numeric(FLERR, arg[iarg++], false, lmp);
  };
  auto word = [&](const std::string &what) -> std::string {
    if (iarg >= narg || stops(iarg)) error->all(FLERR, "{} {}: missing {}", who, model, what);
    return arg[iarg++];
  };
  if (model == "hertz") {
    p.model = TABOR_MODEL_HERTZ;
  } else if (model == "jkr/fixed-grip" || model == "jkr/load-controlled") {
    p.model = model == "jkr/fixed-grip" ? TABOR_MODEL_JKR_FIXED_GRIP : TABOR_MODEL_JKR_LOAD_CONTROLLED;
  } else if (model == "maugis") {
    p.model = TABOR_MODEL_MAUGIS_DUGDALE;
  } else {
    error->all(FLERR, "{}: unknown model {} (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", who, model);
  }
  p.effective_modulus = number("E*");
  if (p.model != TABOR_MODEL_HERTZ) p.work_of_adhesion = number("w");
  // maugis E* w Lambda, or maugis E* w range h | stress s0 (a Lambda per contact)
  bool have_lambda = false;
  if (p.model == TABOR_MODEL_MAUGIS_DUGDALE && !(iarg < narg && (strcmp(arg[iarg], "range") == 0 ||
                                                                 strcmp(arg[iarg], "stress") == 0))) {
    p.tabor_parameter = number("Lambda (or range h | stress s0)");
    have_lambda = true;
  }
  double poisson = 0.0;
  bool have_poisson = false;
  bool stiffness_null = false;
  while (iarg < narg && !stops(iarg)) {
    std::string key = arg[iarg++];
    if (key == "damping") {
      // damping A (Kuwabara-Kono time), or pair granular's damping models with
      // their value after the name (pair granular reads it from the normal
      // model's damping slot, which tabor's normal models do not have)
      std::string what = iarg < narg ? arg[iarg] : "";
      if (what == "viscoelastic" || what == "tsuji" || what == "coeff_restitution") {
        iarg++;
        p.damping_model = what == "viscoelastic" ? TABOR_DAMPING_VISCOELASTIC
            : what == "tsuji"                    ? TABOR_DAMPING_TSUJI
                                                 : TABOR_DAMPING_COEFF_RESTITUTION;
        p.damping_value = number(what == "viscoelastic" ? "damping viscoelastic eta_n0"
                                     : what == "tsuji"  ? "damping tsuji value e"
                                                        : "damping coeff_restitution e");
        p.damping_time = 0.0;
      } else if (what == "velocity" || what == "mass_velocity") {
        error->all(FLERR, "{}: damping {} is not available (viscoelastic, tsuji, coeff_restitution, or a "
                   "Kuwabara-Kono time A)", who, what);
      } else {
        p.damping_model = TABOR_DAMPING_KUWABARA_KONO;
        p.damping_time = number("damping time A (or viscoelastic|tsuji|coeff_restitution VALUE)");
      }
    } else if (key == "poisson") {
      poisson = number("Poisson ratio");
      have_poisson = true;
      if (!(poisson > -1.0 && poisson < 0.5))
        error->all(FLERR, "{}: poisson {} must lie in (-1, 0.5)", who, poisson);
    } else if (key == "tangential") {
      std::string t = word("tangential model");
      if (t == "linear_history") fr.tangential_model = TABOR_TANGENTIAL_LINEAR_HISTORY;
      else if (t == "mindlin") fr.tangential_model = TABOR_TANGENTIAL_MINDLIN;
      else if (t == "mindlin_rescale") fr.tangential_model = TABOR_TANGENTIAL_MINDLIN_RESCALE;
      else if (t == "mindlin_deresiewicz") fr.tangential_model = TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ;
      else
        error->all(FLERR,
                   "{}: unknown tangential model {} (linear_history, mindlin, mindlin_rescale, "
                   "mindlin_deresiewicz)",
                   who, t);
      if (iarg < narg && strcmp(arg[iarg], "NULL") == 0) {
        if (fr.tangential_model == TABOR_TANGENTIAL_LINEAR_HISTORY)
          error->all(FLERR, "{}: tangential linear_history needs a stiffness k_t (N/m), not NULL", who);
        stiffness_null = true;
        iarg++;
      } else {
        fr.tangential_stiffness = number("tangential stiffness k_t");
      }
      fr.tangential_damping = number("tangential damping x_gamma");
      fr.friction_coefficient = number("friction coefficient mu");
    } else if (key == "rolling") {
      std::string r = word("rolling model");
      if (r != "sds") error->all(FLERR, "{}: unknown rolling model {} (sds)", who, r);
      fr.rolling_model = TABOR_ROLLING_SDS;
      fr.rolling_stiffness = number("rolling stiffness k_roll");
      fr.rolling_damping = number("rolling damping gamma_roll");
      fr.rolling_coefficient = number("rolling coefficient mu_roll");
    } else if (key == "twisting") {
      std::string t = word("twisting model");
      if (t == "marshall") {
        fr.twisting_model = TABOR_TWISTING_MARSHALL;
      } else if (t == "sds") {
        fr.twisting_model = TABOR_TWISTING_SDS;
        fr.twisting_stiffness = number("twisting stiffness k_twist");
        fr.twisting_damping = number("twisting damping gamma_twist");
        fr.twisting_coefficient = number("twisting coefficient mu_twist");
      } else {
        error->all(FLERR, "{}: unknown twisting model {} (marshall, sds)", who, t);
      }
    } else if (key == "range" || key == "stress") {
      // ---- per-contact Lambda (maugis only): the material constant h (m) or s0 (Pa);
      // each contact's Lambda = d_n(R*)/h, h = w/s0, follows from its own R* (tabor-ffi)
      if (p.model != TABOR_MODEL_MAUGIS_DUGDALE)
        error->all(FLERR, "{}: keyword {} belongs to maugis, not {}", who, key, model);
      if (have_lambda)
        error->all(FLERR, "{} maugis: {} and a fixed Lambda {} exclude each other (give one)", who, key,
                   p.tabor_parameter);
      if (p.dugdale_range != 0.0 || p.cohesive_stress != 0.0)
        error->all(FLERR, "{} maugis: give one of range and stress (s0 h = w), not both or twice", who);
      std::string text = word(key == "range" ? "range h (m)" : "stress s0 (Pa)");
      char *end = nullptr;
      double value = strtod(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || value <= 0.0)
        error->all(FLERR, "{} maugis: {} {} must be a finite number > 0 ({})", who, key, text,
                   key == "range" ? "m" : "Pa");
      (key == "range" ? p.dugdale_range : p.cohesive_stress) = value;
      // ---- end per-contact Lambda
    } else {
      error->all(FLERR, "{}: unknown keyword {} (poisson, damping, tangential, rolling, twisting, range, stress)",
                 who, key);
    }
  }
  if (stiffness_null) {
    if (!have_poisson)
      error->all(FLERR, "{}: tangential {} NULL needs `poisson nu` (k_t = 8 G*, G* = E* (1 - nu) / (2 (2 - nu)))",
                 who,
                 fr.tangential_model == TABOR_TANGENTIAL_MINDLIN           ? "mindlin"
                     : fr.tangential_model == TABOR_TANGENTIAL_MINDLIN_RESCALE ? "mindlin_rescale"
                                                                               : "mindlin_deresiewicz");
    fr.tangential_stiffness = 8.0 * p.effective_modulus * (1.0 - poisson) / (2.0 * (2.0 - poisson));
  }
  if ((fr.rolling_model != TABOR_ROLLING_NONE || fr.twisting_model != TABOR_TWISTING_NONE) &&
      fr.tangential_model == TABOR_TANGENTIAL_NONE)
    error->all(FLERR, "{}: rolling and twisting need a tangential model (as in pair granular)", who);
  // one contact model for every radius; the reference radius only sets where the
  // exact law is evaluated beyond the table (an overlap 1e6 adhesive depths deep)
  p.effective_radius = 1.0;
  TaborContact *probe = nullptr;
  int status = tabor_contact_new(&p, &fr, &probe);
  if (status != TABOR_OK) tabor_fail_all(lmp, who, status, who == "pair tabor" ? "pair_coeff" : "coefficients");
  tabor_contact_free(probe);
  out.params = p;
  out.friction = fr;
  return iarg;
}

void LAMMPS_NS::tabor_raise_first(LAMMPS *lmp, const std::string &message)
{
  int me = lmp->comm->me, nprocs = lmp->comm->nprocs, first = 0;
  int mine = message.empty() ? nprocs : me;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, lmp->world);
  if (first == nprocs) return;
  int length = me == first ? (int) message.size() : 0;
  MPI_Bcast(&length, 1, MPI_INT, first, lmp->world);
  std::string text(length, ' ');
  if (me == first) text = message;
  MPI_Bcast(&text[0], length, MPI_CHAR, first, lmp->world);
  lmp->error->all(FLERR, text);
}
