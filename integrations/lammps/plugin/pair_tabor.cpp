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

static constexpr std::size_t MAX_RADII_PER_PAIR = 256;

PairTabor::PairTabor(LAMMPS *lmp) :
    Pair(lmp), maxrad(nullptr), fix_history(nullptr), evaluations(0), overflow_reported(0)
{
  single_enable = 0;
  no_virial_fdotr_compute = 1;
  finitecutflag = 1;
}

PairTabor::~PairTabor()
{
  free_laws();
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
  memory->destroy(maxrad);
  if (fix_history && modify->get_fix_by_id("TABOR_HISTORY")) modify->delete_fix("TABOR_HISTORY");
}

void PairTabor::free_laws()
{
  for (auto &c : coeffs) {
    for (auto &l : c.laws) tabor_law_free(l.law);
    c.laws.clear();
  }
}

void PairTabor::check(int status, const char *what)
{
  if (status == TABOR_OK) return;
  char buf[512];
  tabor_last_error(buf, sizeof(buf));
  error->one(FLERR, "pair tabor: {} failed (status {}): {}", what, status, buf);
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
   Lambda: Tabor parameter (used for every effective radius), A: Kuwabara-Kono
   dissipative time (s). */
void PairTabor::coeff(int narg, char **arg)
{
  if (narg < 4) error->all(FLERR, "Incorrect args for pair coefficients (pair tabor)");
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
  p.effective_modulus = number("E*");
  if (model == "hertz") {
    p.model = TABOR_MODEL_HERTZ;
  } else if (model == "jkr/fixed-grip" || model == "jkr/load-controlled") {
    p.model = model == "jkr/fixed-grip" ? TABOR_MODEL_JKR_FIXED_GRIP : TABOR_MODEL_JKR_LOAD_CONTROLLED;
    p.work_of_adhesion = number("w");
  } else if (model == "maugis") {
    p.model = TABOR_MODEL_MAUGIS_DUGDALE;
    p.work_of_adhesion = number("w");
    p.tabor_parameter = number("Lambda");
  } else {
    error->all(FLERR, "pair tabor: unknown model {} (hertz, jkr/fixed-grip, jkr/load-controlled, maugis)", model);
  }
  while (iarg < narg) {
    if (strcmp(arg[iarg], "damping") == 0) {
      iarg++;
      p.damping_time = number("damping time A");
    } else {
      error->all(FLERR, "pair tabor: unknown keyword {}", arg[iarg]);
    }
  }
  // validate once with a unit radius: errors are reported here, not mid-run
  p.effective_radius = 1.0;
  TaborLaw *probe = nullptr;
  check(tabor_law_new(&p, &probe), "pair_coeff");
  tabor_law_free(probe);

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      for (auto &l : coeff_of(i, j).laws) tabor_law_free(l.law);
      coeff_of(i, j) = Coeff();
      coeff_of(i, j).set = 1;
      coeff_of(i, j).params = p;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients (pair tabor)");
}

void PairTabor::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Pair tabor requires atom attributes radius, rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0) error->all(FLERR, "Pair tabor requires ghost atoms store velocity (comm_modify vel yes)");
  if (force->newton_pair)
    error->all(FLERR, "Pair tabor requires newton pair off (its history is kept on both atoms of a pair)");
  neighbor->add_request(this, NeighConst::REQ_SIZE);

  fix_history = dynamic_cast<FixTaborHistory *>(modify->get_fix_by_id("TABOR_HISTORY"));
  if (!fix_history) fix_history = dynamic_cast<FixTaborHistory *>(modify->add_fix("TABOR_HISTORY all tabor/history"));
  if (!fix_history) error->all(FLERR, "pair tabor: could not create fix tabor/history");

  // largest radius per type, over all ranks (as pair granular's maxrad_dynamic)
  int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++)
    local[atom->type[i]] = MAX(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad, n + 1, MPI_DOUBLE, MPI_MAX, world);
}

double PairTabor::init_one(int i, int j)
{
  Coeff &c = coeff_of(MIN(i, j), MAX(i, j));
  if (!c.set) error->all(FLERR, "pair tabor: no pair_coeff for types {} {}", i, j);
  double ri = maxrad[i], rj = maxrad[j];
  if (ri <= 0.0 || rj <= 0.0) return 0.0;
  // the largest effective radius has the largest interaction range (h ∝ R*^(1/3))
  const Law &l = law_for(MIN(i, j), MAX(i, j), ri * rj / (ri + rj));
  double range = l.info.interaction_range;
  if (neighbor->skin < range)
    error->all(FLERR, "pair tabor: neighbor skin {} is below the interaction range {} of types {} {}",
               neighbor->skin, range, i, j);
  return ri + rj + range;
}

const PairTabor::Law &PairTabor::law_for(int itype, int jtype, double rstar)
{
  Coeff &c = coeff_of(itype, jtype);
  for (auto &l : c.laws)
    if (l.rstar == rstar) return l;
  if (c.laws.size() >= MAX_RADII_PER_PAIR)
    error->one(FLERR, "pair tabor: more than {} distinct effective radii for types {} {} "
               "(each needs its own table; polydisperse systems are not supported)",
               MAX_RADII_PER_PAIR, itype, jtype);
  Law l{};
  l.rstar = rstar;
  TaborLawParams p = c.params;
  p.effective_radius = rstar;
  check(tabor_law_new(&p, &l.law), "tabor_law_new");
  check(tabor_law_info(l.law, &l.info), "tabor_law_info");
  c.laws.push_back(l);
  return c.laws.back();
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

  // a one-entry cache of the last law: monodisperse runs never search
  int last_i = -1, last_j = -1;
  double last_r = -1.0;
  const Law *law = nullptr;

  for (int ii = 0; ii < inum; ii++) {
    int i = ilist[ii];
    int itype = type[i];
    int *jlist = firstneigh[i];
    int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj] & NEIGHMASK;
      int jtype = type[j];
      double delx = x[i][0] - x[j][0];
      double dely = x[i][1] - x[j][1];
      double delz = x[i][2] - x[j][2];
      double rsq = delx * delx + dely * dely + delz * delz;
      double radsum = radius[i] + radius[j];
      double rstar = radius[i] * radius[j] / radsum;
      int ti = MIN(itype, jtype), tj = MAX(itype, jtype);
      if (ti != last_i || tj != last_j || rstar != last_r) {
        law = &law_for(ti, tj, rstar);
        last_i = ti;
        last_j = tj;
        last_r = rstar;
      }
      TaborHistory *stored = fix_history->find(i, tag[j]);
      double reach = radsum + law->info.interaction_range;
      if (!stored && rsq >= reach * reach) continue;
      double r = sqrt(rsq);
      double overlap = radsum - r;
      double rinv = 1.0 / r;
      // overlap rate = -(v_i - v_j) . n, n = (x_i - x_j)/r
      double vrn = (v[i][0] - v[j][0]) * delx + (v[i][1] - v[j][1]) * dely + (v[i][2] - v[j][2]) * delz;
      double rate = -vrn * rinv;
      TaborHistory h = stored ? *stored : TaborHistory{0.0, 0.0};
      TaborForce out;
      int status = tabor_law_evaluate(law->law, overlap, rate, &h, &out);
      if (status != TABOR_OK) check(status, "tabor_law_evaluate");
      evaluations++;
      if (stored || h.contact != 0.0) {
        fix_history->store(i, tag[j], h);
        if (j < nlocal) fix_history->store(j, tag[i], h);
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
  if (fix_history->overflow > overflow_reported) {
    overflow_reported = fix_history->overflow;
    error->warning(FLERR, "pair tabor: more than {} contacts on one atom: {} histories dropped",
                   FixTaborHistory::MAXPARTNER, fix_history->overflow);
  }
}

double PairTabor::memory_usage()
{
  return 0.0;
}
