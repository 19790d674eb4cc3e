#include "pair_tabor.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_tabor_history.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;

static const char *const HISTORY_ID = "TABOR_HISTORY";

PairTabor::PairTabor(LAMMPS *lmp) :
    Pair(lmp), maxrad(nullptr), fix_history(nullptr), history_width(TABOR_HISTORY_LEN)
{
  single_enable = 1;
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
  // pair_style and pair_coeff are not stored in restart files: after read_restart
  // include the fragment again (plugin load, pair_style, pair_coeff); the contact
  // histories come back with the atoms (fix tabor/history)
  restartinfo = 0;
}

PairTabor::~PairTabor()
{
  free_laws();
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
  memory->destroy(maxrad);
  if (fix_history && modify->get_fix_by_id(HISTORY_ID)) modify->delete_fix(HISTORY_ID);
}

void PairTabor::free_laws()
{
  for (auto &c : coeffs) {
    tabor_law_free(c.law);
    c.law = nullptr;
  }
}

void PairTabor::fail_all(int status, const char *what)
{
  char buf[512];
  tabor_last_error(buf, sizeof(buf));
  error->all(FLERR, "pair tabor: {} (status {}): {}", what, status, buf);
  throw;    // not reached: error->all does not return
}

void PairTabor::fail_one(int status, const char *what)
{
  char buf[512];
  tabor_last_error(buf, sizeof(buf));
  error->one(FLERR, "pair tabor: {} (status {}): {}", what, status, buf);
  throw;    // not reached
}

void PairTabor::settings(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "Illegal pair_style tabor command: it takes no arguments");
}

/* pair_coeff I J hertz E* [damping A]
   pair_coeff I J jkr/fixed-grip E* w [damping A]
   pair_coeff I J jkr/load-controlled E* w [damping A]
   pair_coeff I J maugis E* w Lambda [damping A]
   E*: effective modulus (Pa), w: work of adhesion (J/m^2, = 2 gamma of LAMMPS jkr),
   Lambda: Tabor parameter (held fixed for every effective radius: the Dugdale
   range h = d_n(R*)/Lambda grows as R*^(1/3)), A: Kuwabara-Kono dissipative
   time (s). Every error is reported on all ranks (error->all). */
void PairTabor::coeff(int narg, char **arg)
{
  if (narg < 4) error->all(FLERR, "Incorrect args for pair coefficients (pair tabor): pair_coeff I J MODEL E* ...");
  if (!allocated) {
    allocated = 1;
    int n = atom->ntypes;
    memory->create(setflag, n + 1, n + 1, "pair:setflag");
    memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
    for (int i = 0; i <= n; i++)
      for (int j = 0; j <= n; j++) setflag[i][j] = 0;
    ntypes_alloc = n;
    coeffs.assign((n + 1) * (n + 1), Coeff());
    memory->create(maxrad, n + 1, "pair:maxrad");
  }
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  TaborLawParams p{};
  std::string model = arg[2];
  int iarg = 3;
  auto number = [&](const char *what) {
    if (iarg >= narg) error->all(FLERR, "pair tabor {}: missing {}", model, what);
    return utils::numeric(FLERR, arg[iarg++], false, lmp);
  };
  if (model == "hertz") {
    p.model = TABOR_MODEL_HERTZ;
  } else if (model == "jkr/fixed-grip" || model == "jkr/load-controlled") {
    p.model = model == "jkr/fixed-grip" ? TABOR_MODEL_JKR_FIXED_GRIP : TABOR_MODEL_JKR_LOAD_CONTROLLED;
  } else if (model == "maugis") {
    p.model = TABOR_MODEL_MAUGIS_DUGDALE;
  } else {
    error->all(FLERR, "pair tabor: unknown model {} (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", model);
  }
  p.effective_modulus = number("E*");
  if (p.model != TABOR_MODEL_HERTZ) p.work_of_adhesion = number("w");
  if (p.model == TABOR_MODEL_MAUGIS_DUGDALE) p.tabor_parameter = number("Lambda");
  while (iarg < narg) {
    if (strcmp(arg[iarg], "damping") == 0) {
      iarg++;
      p.damping_time = number("damping time A");
    } else {
      error->all(FLERR, "pair tabor: unknown keyword {} (damping)", arg[iarg]);
    }
  }
  // one law for every radius; the reference radius only sets where the exact law
  // is evaluated beyond the table (an overlap 1e6 adhesive depths deep)
  p.effective_radius = 1.0;
  TaborLaw *law = nullptr;
  int status = tabor_law_new(&p, &law);
  if (status != TABOR_OK) fail_all(status, "pair_coeff");

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      Coeff &c = coeff_of(i, j);
      tabor_law_free(c.law);
      c = Coeff();
      c.set = 1;
      c.params = p;
      if (count == 0) {
        c.law = law;
      } else {
        status = tabor_law_new(&p, &c.law);
        if (status != TABOR_OK) fail_all(status, "pair_coeff");
      }
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) {
    tabor_law_free(law);
    error->all(FLERR, "Incorrect args for pair coefficients (pair tabor)");
  }
}

void PairTabor::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Pair tabor requires atom attributes radius, rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair tabor requires ghost atoms store velocity (comm_modify vel yes)");
  if (atom->tag_enable == 0) error->all(FLERR, "Pair tabor requires atom IDs");
  // a newton-off half list whatever the newton setting: a pair across two ranks
  // is computed on both (each applies the force to its own atom and keeps the
  // contact's history with it), so no reverse communication of history is needed
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_NEWTON_OFF);

  // the history fix: recreated after read_restart with the same ID and style,
  // LAMMPS hands it the histories stored in the restart file
  fix_history = dynamic_cast<FixTaborHistory *>(modify->get_fix_by_id(HISTORY_ID));
  if (fix_history && fix_history->width() != history_width) {
    modify->delete_fix(HISTORY_ID);
    fix_history = nullptr;
  }
  if (!fix_history)
    fix_history = dynamic_cast<FixTaborHistory *>(
        modify->add_fix(fmt::format("{} all tabor/history {}", HISTORY_ID, history_width)));
  if (!fix_history) error->all(FLERR, "pair tabor: could not create fix tabor/history");

  // largest radius per type, over all ranks (as pair granular's maxrad_dynamic)
  int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = MAX(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad, n + 1, MPI_DOUBLE, MPI_MAX, world);
}

double PairTabor::init_one(int i, int j)
{
  Coeff &c = coeff_of(i, j);
  if (!c.set) error->all(FLERR, "pair tabor: no pair_coeff for types {} {}", i, j);
  double ri = maxrad[i], rj = maxrad[j];
  c.reach = 0.0;
  if (ri <= 0.0 || rj <= 0.0) return 0.0;
  // the largest effective radius has the largest interaction range (∝ R*^(1/3))
  TaborLawInfo info;
  int status = tabor_law_info_at(c.law, ri * rj / (ri + rj), &info);
  if (status != TABOR_OK) fail_all(status, "init");
  c.reach = info.interaction_range;
  if (neighbor->skin < c.reach)
    error->all(FLERR, "pair tabor: neighbor skin {} is below the interaction range {} of types {} {}",
               neighbor->skin, c.reach, i, j);
  return ri + rj + c.reach;
}

void PairTabor::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  double *radius = atom->radius;
  int *type = atom->type;
  tagint *tag = atom->tag;
  int nlocal = atom->nlocal;

  int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  std::vector<double> h(history_width);

  for (int ii = 0; ii < inum; ii++) {
    int i = ilist[ii];
    int itype = type[i];
    int *jlist = firstneigh[i];
    int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj] & NEIGHMASK;
      const Coeff &c = coeff_of(itype, type[j]);
      double delx = x[i][0] - x[j][0];
      double dely = x[i][1] - x[j][1];
      double delz = x[i][2] - x[j][2];
      double rsq = delx * delx + dely * dely + delz * delz;
      double radsum = radius[i] + radius[j];
      double *stored = fix_history->find(i, tag[j]);
      double reach = radsum + c.reach;
      if (!stored && rsq >= reach * reach) continue;
      double rstar = radius[i] * radius[j] / radsum;
      double r = sqrt(rsq);
      double overlap = radsum - r;
      double rinv = 1.0 / r;
      // overlap rate = -(v_i - v_j) . n, n = (x_i - x_j)/r
      double vrn = (v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely + (v[i][2] - v[j][2]) * delz;
      double rate = -vrn * rinv;
      if (stored) std::memcpy(h.data(), stored, sizeof(double) * history_width);
      else std::fill(h.begin(), h.end(), 0.0);
      auto *hist = reinterpret_cast<TaborHistory *>(h.data());
      TaborForce out;
      int status = tabor_law_evaluate_at(c.law, rstar, overlap, rate, hist, &out);
      if (status != TABOR_OK) fail_one(status, "tabor_law_evaluate_at");
      if (stored || h[0] != 0.0) {
        fix_history->store(i, tag[j], h.data());
        if (j < nlocal) fix_history->store(j, tag[i], h.data());
      }
      if (out.force == 0.0) continue;
      double fpair = out.force * rinv;
      double fx = delx * fpair, fy = dely * fpair, fz = delz * fpair;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      if (j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
      }
      if (evflag) ev_tally_xyz(i, j, nlocal, 0, 0.0, 0.0, fx, fy, fz, delx, dely, delz);
    }
  }
}

/* the force between i and j as compute pair/local sees it: the stored history of
   the contact is read, not advanced; the energy is not tallied (0) */
double PairTabor::single(int i, int j, int itype, int jtype, double rsq, double /*factor_coul*/,
                         double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  const Coeff &c = coeff_of(itype, jtype);
  double *radius = atom->radius;
  double radsum = radius[i] + radius[j];
  double *stored = fix_history->find(i, atom->tag[j]);
  if (!stored && j < atom->nlocal) stored = fix_history->find(j, atom->tag[i]);
  double reach = radsum + c.reach;
  if (!stored && rsq >= reach * reach) return 0.0;
  double **x = atom->x;
  double **v = atom->v;
  double r = sqrt(rsq);
  double delx = x[i][0] - x[j][0], dely = x[i][1] - x[j][1], delz = x[i][2] - x[j][2];
  double vrn = (v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely + (v[i][2] - v[j][2]) * delz;
  std::vector<double> h(history_width, 0.0);
  if (stored) std::memcpy(h.data(), stored, sizeof(double) * history_width);
  TaborForce out;
  int status = tabor_law_evaluate_at(c.law, radius[i] * radius[j] / radsum, radsum - r, -vrn / r,
                                     reinterpret_cast<TaborHistory *>(h.data()), &out);
  if (status != TABOR_OK) fail_one(status, "tabor_law_evaluate_at (single)");
  fforce = out.force / r;
  return 0.0;
}

double PairTabor::memory_usage()
{
  return (double) coeffs.size() * sizeof(Coeff);
}
