#include "tabor_coeff.h"

#include "atom.h"
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
   Or LAMMPS's material form, MODEL PARAMETERS = material E nu gamma MODEL [Lambda]
   (Young's modulus, Poisson's ratio, surface energy per surface, as pair
   granular's jkr E eta nu gamma): E* = 1/(2 (1 - nu^2)/E) (pair granular's
   mix_stiffnessE(E, E, nu, nu); fix wall/gran's E/(2 (1 - nu^2)) for a wall),
   w = 2 gamma (LAMMPS's JKR force 4 E* a^3/(3 R) - 2 pi a^2 sqrt(4 gamma E* / (pi a))
   is JKR's with w = 2 gamma), k_t NULL = 8 G* with G* = 1/(4 (2 - nu)(1 + nu)/E);
   a wall's own material (wall_material E_w nu_w gamma_w) mixes as two types do.
   Every error is reported on all ranks (error->all). */
int LAMMPS_NS::tabor_parse_coeff(LAMMPS *lmp, const std::string &who, int narg, char **arg, int first,
                                 const std::vector<std::string> &stop, TaborCoeff &out)
{
  Error *error = lmp->error;
  TaborLawParams p{};
  TaborFrictionParams fr{};
  const bool wall = who != "pair tabor";
  int iarg = first;
  // ---- LAMMPS's material form: material E nu gamma MODEL ... (pair granular's
  // jkr E eta nu gamma without eta: damping is a keyword here)
  bool material = iarg < narg && strcmp(arg[iarg], "material") == 0;
  TaborMaterial mat, wall_mat;
  bool have_wall_mat = false;
  auto read_material = [&](const std::string &key, TaborMaterial &m) {
    auto value = [&](const char *what) {
      if (iarg >= narg) error->all(FLERR, "{} {}: missing {} (give {} E nu gamma)", who, key, what, key);
      if (!utils::is_double(arg[iarg]))
        error->all(FLERR, "{} {}: {} must be a number, not {} (give {} E nu gamma)", who, key, what, arg[iarg], key);
      return utils::numeric(FLERR, arg[iarg++], false, lmp);
    };
    m.youngs = value("Young's modulus E");
    m.poisson = value("Poisson's ratio nu");
    m.gamma = value("surface energy gamma");
    if (!(m.youngs > 0.0) || !std::isfinite(m.youngs))
      error->all(FLERR, "{} {}: Young's modulus E {} must be a finite number > 0", who, key, m.youngs);
    if (!(m.poisson > -1.0 && m.poisson < 0.5))
      error->all(FLERR, "{} {}: Poisson's ratio nu {} must lie in (-1, 0.5)", who, key, m.poisson);
    if (!(m.gamma >= 0.0) || !std::isfinite(m.gamma))
      error->all(FLERR, "{} {}: surface energy gamma {} must be a finite number >= 0 (per surface: w = 2 gamma)",
                 who, key, m.gamma);
  };
  if (material) {
    iarg++;
    read_material("material", mat);
  }
  if (iarg >= narg)
    error->all(FLERR, "{}: missing the model (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", who);
  std::string model = arg[iarg++];
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
  } else if (model == "material") {
    error->all(FLERR, "{}: material comes first (material E nu gamma MODEL ...), once", who);
  } else {
    error->all(FLERR, "{}: unknown model {} (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", who, model);
  }
  if (material) {
    if (p.model == TABOR_MODEL_HERTZ && mat.gamma != 0.0)
      error->all(FLERR, "{} material: hertz has no adhesion: surface energy gamma {} must be 0", who, mat.gamma);
    // both bodies of one material: pair granular's mix_stiffnessE(E, E, nu, nu),
    // and fix wall/gran's E/(2 (1 - nu^2)) for a wall
    p.effective_modulus = wall ? mat.youngs / (2.0 * (1.0 - mat.poisson * mat.poisson))
                               : tabor_mix_modulus(mat, mat);
    if (p.model != TABOR_MODEL_HERTZ) p.work_of_adhesion = 2.0 * mat.gamma;
  } else {
    p.effective_modulus = number("E*");
    if (p.model != TABOR_MODEL_HERTZ) p.work_of_adhesion = number("w");
  }
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
    } else if (key == "wall_material") {
      if (!wall || !material)
        error->all(FLERR, "{}: wall_material belongs to a wall fix in the material form (material E nu gamma "
                   "MODEL ... wall_material E_w nu_w gamma_w)", who);
      if (have_wall_mat) error->all(FLERR, "{}: wall_material given twice", who);
      read_material("wall_material", wall_mat);
      have_wall_mat = true;
    } else if (key == "poisson") {
      if (material)
        error->all(FLERR, "{}: poisson belongs to the E* form; the material form takes nu after E "
                   "(material E nu gamma)", who);
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
      error->all(FLERR, "{}: unknown keyword {} (poisson, damping, tangential, rolling, twisting, range, stress, wall_material)",
                 who, key);
    }
  }
  if (material && have_wall_mat) {
    // the wall's own material, mixed with the particles' as two types would be
    if (p.model == TABOR_MODEL_HERTZ && wall_mat.gamma != 0.0)
      error->all(FLERR, "{} wall_material: hertz has no adhesion: surface energy gamma {} must be 0", who,
                 wall_mat.gamma);
    p.effective_modulus = tabor_mix_modulus(mat, wall_mat);
    if (p.model != TABOR_MODEL_HERTZ) p.work_of_adhesion = 2.0 * sqrt(mat.gamma * wall_mat.gamma);
  }
  if (stiffness_null && material) {
    // 8 G*: pair granular's mix_stiffnessG(E, E, nu, nu) for one material,
    // mix_stiffnessG_wall E/(4 (2 - nu)(1 + nu)) for a wall of it
    double g = have_wall_mat ? tabor_mix_shear(mat, wall_mat)
        : wall               ? mat.youngs / (4.0 * (2.0 - mat.poisson) * (1.0 + mat.poisson))
                             : tabor_mix_shear(mat, mat);
    fr.tangential_stiffness = 8.0 * g;
  } else if (stiffness_null) {
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
  std::string why = tabor_probe_contact(probe, fr);
  tabor_contact_free(probe);
  if (!why.empty()) error->all(FLERR, "{}: {}: {}", who, who == "pair tabor" ? "pair_coeff" : "coefficients", why);
  out.params = p;
  out.friction = fr;
  out.material = material;
  out.mat = mat;
  out.stiffness_null = stiffness_null;
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

double LAMMPS_NS::tabor_mix_modulus(const TaborMaterial &a, const TaborMaterial &b)
{
  double fa = (1.0 - a.poisson * a.poisson) / a.youngs;
  double fb = (1.0 - b.poisson * b.poisson) / b.youngs;
  return 1.0 / (fa + fb);
}

double LAMMPS_NS::tabor_mix_shear(const TaborMaterial &a, const TaborMaterial &b)
{
  double fa = 2.0 * (2.0 - a.poisson) * (1.0 + a.poisson) / a.youngs;
  double fb = 2.0 * (2.0 - b.poisson) * (1.0 + b.poisson) / b.youngs;
  return 1.0 / (fa + fb);
}

/* pair granular's mix_geom, sqrt(c_i c_j), for every coefficient but the moduli
   and k_t NULL (LAMMPS's GranSubMod::mix_coeffs and its overrides for the
   material normal models and mindlin) */
std::string LAMMPS_NS::tabor_mix_coeff(const TaborCoeff &a, const TaborCoeff &b, TaborCoeff &out)
{
  static const char *const models[] = {"hertz", "jkr/fixed-grip", "jkr/load-controlled", "maugis"};
  const TaborLawParams &pa = a.params, &pb = b.params;
  const TaborFrictionParams &fa = a.friction, &fb = b.friction;
  if (!a.material || !b.material) return "only the material form (material E nu gamma MODEL ...) mixes";
  if (pa.model != pb.model) {
    auto name = [&](int m) { return m >= 0 && m < 4 ? models[m] : "?"; };
    return std::string("the models differ (") + name(pa.model) + ", " + name(pb.model) + ")";
  }
  auto form = [](const TaborLawParams &p) {
    return p.dugdale_range != 0.0 ? "range h" : p.cohesive_stress != 0.0 ? "stress s0" : "a fixed Lambda";
  };
  if (pa.model == TABOR_MODEL_MAUGIS_DUGDALE && std::string(form(pa)) != form(pb))
    return std::string("maugis is given with ") + form(pa) + " and with " + form(pb);
  if (pa.damping_model != pb.damping_model || (pa.damping_time != 0.0) != (pb.damping_time != 0.0))
    return "the damping models differ";
  if (fa.tangential_model != fb.tangential_model) return "the tangential models differ";
  if (fa.rolling_model != fb.rolling_model) return "the rolling models differ";
  if (fa.twisting_model != fb.twisting_model) return "the twisting models differ";
  auto geom = [](double x, double y) { return sqrt(x * y); };
  TaborLawParams p = pa;
  TaborFrictionParams f = fa;
  p.effective_modulus = tabor_mix_modulus(a.mat, b.mat);
  p.work_of_adhesion = pa.model == TABOR_MODEL_HERTZ ? 0.0 : 2.0 * geom(a.mat.gamma, b.mat.gamma);
  p.tabor_parameter = geom(pa.tabor_parameter, pb.tabor_parameter);
  p.dugdale_range = geom(pa.dugdale_range, pb.dugdale_range);
  p.cohesive_stress = geom(pa.cohesive_stress, pb.cohesive_stress);
  p.damping_time = geom(pa.damping_time, pb.damping_time);
  p.damping_value = geom(pa.damping_value, pb.damping_value);
  bool null = a.stiffness_null || b.stiffness_null;
  f.tangential_stiffness = null ? 8.0 * tabor_mix_shear(a.mat, b.mat)
                                : geom(fa.tangential_stiffness, fb.tangential_stiffness);
  f.tangential_damping = geom(fa.tangential_damping, fb.tangential_damping);
  f.friction_coefficient = geom(fa.friction_coefficient, fb.friction_coefficient);
  f.rolling_stiffness = geom(fa.rolling_stiffness, fb.rolling_stiffness);
  f.rolling_damping = geom(fa.rolling_damping, fb.rolling_damping);
  f.rolling_coefficient = geom(fa.rolling_coefficient, fb.rolling_coefficient);
  f.twisting_stiffness = geom(fa.twisting_stiffness, fb.twisting_stiffness);
  f.twisting_damping = geom(fa.twisting_damping, fb.twisting_damping);
  f.twisting_coefficient = geom(fa.twisting_coefficient, fb.twisting_coefficient);
  out = TaborCoeff();
  out.params = p;
  out.friction = f;
  out.material = false;    // a mixed pair is not itself a material
  out.stiffness_null = null;
  return "";
}

int LAMMPS_NS::tabor_restart_offset(LAMMPS *lmp, int nlocal, int nth, std::string &problem)
{
  const double *extra = lmp->atom->extra[nlocal];
  const double room = lmp->atom->nextra_store;
  double m = 0.0;
  for (int i = 0; i < nth; i++) {
    double length = extra[static_cast<int>(m)];
    if (!std::isfinite(length) || length != std::floor(length) || length < 1.0 || m + length >= room) {
      problem = fmt::format("follows a record of {} values (the record of fix {} of the atom, at value {}): a "
                            "corrupted restart file", length, i + 1, m);
      return -1;
    }
    m += length;
  }
  return static_cast<int>(m);
}

std::string LAMMPS_NS::tabor_history_problem(const double *h, int width)
{
  for (int d = 0; d < width; d++)
    if (!std::isfinite(h[d])) return fmt::format("the non-finite history value {} (double {})", h[d], d);
  if (h[0] != 0.0 && h[0] != 1.0) return fmt::format("the contact flag {} (0 or 1)", h[0]);
  if (width >= TABOR_CONTACT_HISTORY_LEN) {
    // the micro-slip bed's header: node spacing and last squared contact radius
    // (only in a whole bed: a shorter record is another layout, e.g. Thornton's
    // 16 doubles, whose doubles 13 and 14 are a reversal force and a mode, and
    // which the callers name; reading the header there would also read past it)
    const double *bed = h + TABOR_CONTACT_HISTORY_BASE_LEN;
    double dz = bed[3], a0_sq = bed[4];
    int nodes = (TABOR_MICRO_SLIP_LEN - 5) / 2;
    if (dz < 0.0 || a0_sq < 0.0 || (dz > 0.0 && a0_sq > nodes * dz))
      return fmt::format("the micro-slip bed header spacing {}, squared radius {} (both >= 0, the radius "
                         "inside {} nodes)", dz, a0_sq, nodes);
  }
  return "";
}

LAMMPS_NS::TaborHistoryFit LAMMPS_NS::tabor_history_fit(const double *h, int stored, int kept)
{
  bool thornton = stored == 16 && TABOR_CONTACT_HISTORY_LEN != 16;
  for (int d = thornton ? TABOR_CONTACT_HISTORY_BASE_LEN : kept; d < stored; d++)
    if (h[d] != 0.0) return thornton ? TABOR_HISTORY_THORNTON : TABOR_HISTORY_DROPPED;
  return TABOR_HISTORY_FITS;
}

void LAMMPS_NS::tabor_check_atoms(LAMMPS *lmp, const std::string &who, int groupbit)
{
  Atom *atom = lmp->atom;
  auto problem = [&](int i) -> std::string {
    if (atom->type[i] < 1 || atom->type[i] > atom->ntypes)
      return fmt::format("type {} (1 to {})", atom->type[i], atom->ntypes);
    double r = atom->radius[i];
    if (!(r > 0.0) || !std::isfinite(r))
      return fmt::format("radius {}: every particle needs a finite radius > 0 (a point particle cannot touch; set "
                         "its diameter)", r);
    if (!(atom->rmass[i] > 0.0) || !std::isfinite(atom->rmass[i]))
      return fmt::format("mass {} (a finite mass > 0)", atom->rmass[i]);
    // a sphere's moment of inertia that underflows or overflows: no spin can be integrated
    double inertia = 0.4 * atom->rmass[i] * r * r;
    if (!(inertia > 0.0) || !std::isfinite(inertia))
      return fmt::format("radius {} and mass {}: the moment of inertia 0.4 m r^2 = {} is not a finite number > 0",
                         r, atom->rmass[i], inertia);
    const char *names[3] = {"position", "velocity", "angular velocity"};
    double *vectors[3] = {atom->x[i], atom->v[i], atom->omega[i]};
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++)
        if (!std::isfinite(vectors[k][d]))
          return fmt::format("{} ({}, {}, {}) (finite)", names[k], vectors[k][0], vectors[k][1], vectors[k][2]);
    return "";
  };
  tagint bad = MAXTAGINT;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && !problem(i).empty()) bad = MIN(bad, atom->tag[i]);
  tagint worst = MAXTAGINT;
  MPI_Allreduce(&bad, &worst, 1, MPI_LMP_TAGINT, MPI_MIN, lmp->world);
  if (worst == MAXTAGINT) return;
  std::string message;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->tag[i] == worst && (atom->mask[i] & groupbit))
      message = fmt::format("{}: atom {} (type {}) has {}", who, worst, atom->type[i], problem(i));
  tabor_raise_first(lmp, message);
}

/* tabor_contact_new checks the normal law (finite from its snap-off overlap to 1
   cm at R* = 1 m, at rest and moving); the friction models are checked here on
   the same scale: two steps of a contact of two 2 m spheres overlapping by 1 cm,
   sliding at 1 m/s and spinning at 1 rad/s, with a time step of 1 ms. A
   tangential, rolling or twisting stiffness so large that its force overflows
   there is refused now, on every rank, not by one rank's contact step during the
   run. */
std::string LAMMPS_NS::tabor_probe_contact(TaborContact *contact, const TaborFrictionParams &fr)
{
  if (fr.tangential_model == TABOR_TANGENTIAL_NONE) return "";
  TaborContactState s{};
  s.normal[0] = 1.0;
  s.overlap = 1e-2;
  s.radius_i = s.radius_j = 2.0;
  const double v[3] = {-0.1, 1.0, 0.5}, wi[3] = {1.0, -0.5, 1.0}, wj[3] = {-1.0, 0.5, 0.3};
  for (int k = 0; k < 3; k++) {
    s.relative_velocity[k] = v[k];
    s.angular_velocity_i[k] = wi[k];
    s.angular_velocity_j[k] = wj[k];
  }
  s.time_step = 1e-3;
  s.effective_mass = 1.0;
  s.update_history = 1;
  TaborContactHistory h;
  std::memset(&h, 0, sizeof(h));
  TaborContactForces out;
  for (int step = 0; step < 2; step++) {
    int status = tabor_contact_step(contact, &s, &h, &out);
    if (status != TABOR_OK) {
      char buf[512];
      tabor_last_error(buf, sizeof(buf));
      return fmt::format("the friction model (tangential k_t = {}, x_gamma = {}, mu = {}; rolling {} {} {}; "
                         "twisting {} {} {}) does not answer finitely for a contact at R* = 1 m sliding at 1 m/s "
                         "(status {}): {}", fr.tangential_stiffness, fr.tangential_damping,
                         fr.friction_coefficient, fr.rolling_stiffness, fr.rolling_damping, fr.rolling_coefficient,
                         fr.twisting_stiffness, fr.twisting_damping, fr.twisting_coefficient, status, buf);
    }
  }
  return "";
}
