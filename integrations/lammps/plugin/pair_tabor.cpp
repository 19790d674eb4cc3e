#include "pair_tabor.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_tabor_history.h"
#include "tabor_coeff.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

using namespace LAMMPS_NS;

static const char *const HISTORY_ID = "TABOR_HISTORY";

PairTabor::PairTabor(LAMMPS *lmp) :
    Pair(lmp), maxrad(nullptr), fix_history(nullptr), history_width(TABOR_CONTACT_HISTORY_LEN)
{
  single_enable = 1;
  // compute pair/local p1..p4: normal force, tangential force, contact radius, F_n0
  single_extra = 4;
  svector = new double[single_extra];
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
  delete[] svector;
  if (fix_history && modify->get_fix_by_id(HISTORY_ID)) modify->delete_fix(HISTORY_ID);
}

void PairTabor::free_laws()
{
  for (auto &c : coeffs) {
    tabor_contact_free(c.contact);
    c.contact = nullptr;
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
  tabor_fail_rank(lmp, FLERR, "pair tabor: {} (status {}): {}", what, status, buf);
  throw;    // not reached
}

void PairTabor::settings(int narg, char ** /*arg*/)
{
  if (narg != 0) error->all(FLERR, "Illegal pair_style tabor command: it takes no arguments");
}

/* pair_coeff I J MODEL ARGS [KEYWORDS]: parsed by tabor_parse_coeff (tabor_coeff.cpp),
   shared with fix wall/tabor. Every error is reported on all ranks (error->all). */
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

  TaborCoeff parsed;
  tabor_parse_coeff(lmp, "pair tabor", narg, arg, 2, {}, parsed);
  const TaborLawParams &p = parsed.params;
  const TaborFrictionParams &fr = parsed.friction;
  int status;

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      Coeff &c = coeff_of(i, j);
      tabor_contact_free(c.contact);
      c = Coeff();
      c.set = 1;
      c.given = parsed;
      c.params = p;
      c.friction = fr;
      status = tabor_contact_new(&p, &fr, &c.contact);
      if (status != TABOR_OK) fail_all(status, "pair_coeff");
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients (pair tabor)");
}

void PairTabor::init_style()
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "Pair tabor requires atom attributes radius, rmass (atom_style sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "Pair tabor requires ghost atoms store velocity (comm_modify vel yes)");
  if (atom->tag_enable == 0) error->all(FLERR, "Pair tabor requires atom IDs");
  if (!atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "Pair tabor requires atom attributes omega, torque (atom_style sphere)");
  // a newton-off half list whatever the newton setting: a pair across two ranks
  // is computed on both (each applies the force to its own atom and keeps the
  // contact's history with it), so no reverse communication of history is needed
  neighbor->add_request(this, NeighConst::REQ_SIZE | NeighConst::REQ_NEWTON_OFF);

  // the history fix: recreated after read_restart with the same ID and style,
  // LAMMPS hands it the histories stored in the restart file
  // the doubles per contact: the micro-slip bed only where a pair coefficient
  // uses mindlin_deresiewicz (tabor_contact_history_len)
  history_width = TABOR_CONTACT_HISTORY_BASE_LEN;
  for (auto &c : coeffs)
    if (c.set && c.contact) history_width = MAX(history_width, (int) tabor_contact_history_len(c.contact));
  fix_history = dynamic_cast<FixTaborHistory *>(modify->get_fix_by_id(HISTORY_ID));
  if (fix_history) fix_history->set_width(history_width);
  if (!fix_history)
    fix_history = dynamic_cast<FixTaborHistory *>(
        modify->add_fix(fmt::format("{} all tabor/history {}", HISTORY_ID, history_width)));
  if (!fix_history) error->all(FLERR, "pair tabor: could not create fix tabor/history");
  // a restart record refused when the fix read it: one error on every rank
  fix_history->check_restart();
  fix_history->refresh_stamps();

  // an atom no contact law can take (a point particle of radius 0, a type out of
  // range, a non-finite position, velocity or spin, as a corrupted restart file
  // can hold) is refused here on every rank (error->all), naming the lowest such
  // atom ID, rather than by the contact step of one rank during the run
  tabor_check_atoms(lmp, "pair tabor", 1);

  // largest radius per type, over all ranks (as pair granular's maxrad_dynamic)
  int n = atom->ntypes;
  std::vector<double> local(n + 1, 0.0);
  for (int i = 0; i < atom->nlocal; i++) local[atom->type[i]] = MAX(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), maxrad, n + 1, MPI_DOUBLE, MPI_MAX, world);
  // and the smallest (the per-contact Lambda table covers [R*min, R*max])
  std::vector<double> small(n + 1, std::numeric_limits<double>::infinity());
  for (int i = 0; i < atom->nlocal; i++) small[atom->type[i]] = MIN(small[atom->type[i]], atom->radius[i]);
  minrad.assign(n + 1, std::numeric_limits<double>::infinity());
  MPI_Allreduce(small.data(), minrad.data(), n + 1, MPI_DOUBLE, MPI_MIN, world);
}

double PairTabor::init_one(int i, int j)
{
  Coeff &c = coeff_of(i, j);
  if (!c.set) mix(i, j);
  double ri = maxrad[i], rj = maxrad[j];
  c.reach = 0.0;
  if (ri <= 0.0 || rj <= 0.0) return 0.0;
  // the largest interaction range over the pair's effective radii (at the largest
  // for a fixed Lambda, ∝ R*^(1/3)); a per-contact Lambda law builds its table
  // for [R*min, R*max] now, on every rank alike (contacts outside still work)
  double si = MIN(minrad[i], ri), sj = MIN(minrad[j], rj);
  int status = tabor_contact_prepare(c.contact, si * sj / (si + sj), ri * rj / (ri + rj), &c.reach);
  if (status != TABOR_OK) fail_all(status, "init");
  if (neighbor->skin < c.reach)
    error->all(FLERR, "pair tabor: neighbor skin {} is below the interaction range {} of types {} {}",
               neighbor->skin, c.reach, i, j);
  return ri + rj + c.reach;
}

/* Types I != J without a pair_coeff line of their own: mixed from the material
   forms of I I and J J as pair granular mixes them (tabor_mix_coeff), again at
   every init (a later pair_coeff I I changes it); the contact model is rebuilt
   only when the mixed parameters change. Refused on every rank (error->all) when
   it cannot be mixed, naming the types and the reason. */
void PairTabor::mix(int i, int j)
{
  Coeff &c = coeff_of(i, j);
  const Coeff &a = coeff_of(i, i), &b = coeff_of(j, j);
  if (i == j || !a.set || !b.set)
    error->all(FLERR, "pair tabor: no pair_coeff for types {} {}, and it cannot be mixed without pair_coeff {} {}",
               i, j, a.set ? j : i, a.set ? j : i);
  TaborCoeff m;
  std::string why = tabor_mix_coeff(a.given, b.given, m);
  if (!why.empty())
    error->all(FLERR, "pair tabor: no pair_coeff for types {} {}, and pair_coeff {} {} and {} {} cannot be mixed: {}",
               i, j, i, i, j, j, why);
  // field by field (a memcmp would see the structs' padding)
  const TaborLawParams &p = c.params, &q = m.params;
  const TaborFrictionParams &f = c.friction, &g = m.friction;
  bool same = p.model == q.model && p.effective_modulus == q.effective_modulus &&
      p.work_of_adhesion == q.work_of_adhesion && p.tabor_parameter == q.tabor_parameter &&
      p.damping_time == q.damping_time && p.damping_model == q.damping_model &&
      p.damping_value == q.damping_value && p.dugdale_range == q.dugdale_range &&
      p.cohesive_stress == q.cohesive_stress && p.effective_radius == q.effective_radius &&
      f.tangential_model == g.tangential_model && f.tangential_stiffness == g.tangential_stiffness &&
      f.tangential_damping == g.tangential_damping && f.friction_coefficient == g.friction_coefficient &&
      f.rolling_model == g.rolling_model && f.rolling_stiffness == g.rolling_stiffness &&
      f.rolling_damping == g.rolling_damping && f.rolling_coefficient == g.rolling_coefficient &&
      f.twisting_model == g.twisting_model && f.twisting_stiffness == g.twisting_stiffness &&
      f.twisting_damping == g.twisting_damping && f.twisting_coefficient == g.twisting_coefficient;
  if (c.mixed && c.contact && same) return;
  tabor_contact_free(c.contact);
  c = Coeff();
  c.mixed = 1;
  c.given = m;
  c.params = m.params;
  c.friction = m.friction;
  int status = tabor_contact_new(&c.params, &c.friction, &c.contact);
  if (status != TABOR_OK) {
    char buf[512];
    tabor_last_error(buf, sizeof(buf));
    error->all(FLERR, "pair tabor: types {} {} mixed from pair_coeff {} {} and {} {} (status {}): {}", i, j, i, i, j,
               j, status, buf);
  }
  std::string probe = tabor_probe_contact(c.contact, c.friction);
  if (!probe.empty())
    error->all(FLERR, "pair tabor: types {} {} mixed from pair_coeff {} {} and {} {}: {}", i, j, i, i, j, j, probe);
}

/* One contact, evaluated with the atom of the lower tag as body 1 (whatever the
   neighbor list's order), so that the ranks that both compute a pair across a
   sub-domain boundary do the same arithmetic and keep the same history; the
   history is stored identically on both atoms. Returns 0 when the pair is beyond
   reach and has no history; `first` is 1 when i is body 1. */
int PairTabor::evaluate(int i, int j, int update_history, TaborContactForces &out, int &first)
{
  double **x = atom->x;
  double *radius = atom->radius;
  tagint *tag = atom->tag;
  const Coeff &c = coeff_of(atom->type[i], atom->type[j]);
  first = tag[i] < tag[j];
  int a = first ? i : j, b = first ? j : i;
  double del[3] = {x[a][0] - x[b][0], x[a][1] - x[b][1], x[a][2] - x[b][2]};
  double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
  double radsum = radius[a] + radius[b];
  double *stored = fix_history->find(i, tag[j], fix_history->stamp_of(j));
  double reach = radsum + c.reach;
  if (!stored && rsq >= reach * reach) return 0;
  // a history of many cache lines (the micro-slip bed): fetch all of them, and
  // those of the copy on j, at once rather than one miss after another
  if (stored && history_width > 16) {
    double *other = j < atom->nlocal ? fix_history->find(j, tag[i], fix_history->stamp_of(i)) : nullptr;
    for (int k = 0; k < history_width; k += 8) {
      __builtin_prefetch(stored + k, 1);
      if (other) __builtin_prefetch(other + k, 1);
    }
  }
  double r = sqrt(rsq);
  double rinv = 1.0 / r;
  double **v = atom->v;
  double **omega = atom->omega;
  TaborContactState s;
  for (int k = 0; k < 3; k++) {
    s.normal[k] = del[k] * rinv;
    s.relative_velocity[k] = v[a][k] - v[b][k];
    s.angular_velocity_i[k] = omega[a][k];
    s.angular_velocity_j[k] = omega[b][k];
  }
  s.overlap = radsum - r;
  s.radius_i = radius[a];
  s.radius_j = radius[b];
  s.time_step = update->dt;
  double *rmass = atom->rmass;
  s.effective_mass = rmass[a] * rmass[b] / (rmass[a] + rmass[b]);
  s.update_history = update_history > 0 ? 1 : 0;
  // a stored history of the full width is stepped where it lies (the micro-slip
  // bed is most of it); a narrower one, or none, in a zero-padded copy; single()
  // (update_history < 0) must not change it: always a copy
  TaborContactHistory local;
  TaborContactHistory *h = &local;
  if (stored && update_history >= 0 && history_width == TABOR_CONTACT_HISTORY_LEN) {
    h = reinterpret_cast<TaborContactHistory *>(stored);
  } else {
    std::memset(&local, 0, sizeof(local));
    if (stored) std::memcpy(&local, stored, sizeof(double) * history_width);
  }
  int status = tabor_contact_step(c.contact, &s, h, &out);
  if (status != TABOR_OK) fail_one(status, "tabor_contact_step");
  if (update_history >= 0 && (stored || h->contact != 0.0)) {
    // j first: storing for i may remove the entry h points into (contact broken)
    if (j < atom->nlocal) fix_history->store(j, tag[i], fix_history->stamp_of(i), reinterpret_cast<double *>(h));
    fix_history->store(i, tag[j], fix_history->stamp_of(j), reinterpret_cast<double *>(h));
  }
  return 1;
}

void PairTabor::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);

  double **x = atom->x;
  double **f = atom->f;
  double **torque = atom->torque;
  int nlocal = atom->nlocal;
  // pair granular's convention: the setup force call of a run does not advance
  // the friction displacements
  int update_history = update->setupflag ? 0 : 1;

  int inum = list->inum;
  int *ilist = list->ilist;
  int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  // after each neighbor list build: the ghosts' creation stamps, and the records
  // of partners that are gone (deleted atoms) dropped
  if (neighbor->ago == 0) {
    comm->forward_comm(fix_history);
    fix_history->drop_orphans(inum, ilist, numneigh, firstneigh);
  }

  for (int ii = 0; ii < inum; ii++) {
    int i = ilist[ii];
    int *jlist = firstneigh[i];
    int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj] & NEIGHMASK;
      TaborContactForces out;
      int first;
      if (!evaluate(i, j, update_history, out, first)) continue;
      if (out.normal_force == 0.0 && out.tangential_force == 0.0) continue;
      // force on i
      double sign = first ? 1.0 : -1.0;
      double fx = sign * out.force[0], fy = sign * out.force[1], fz = sign * out.force[2];
      const double *ti = first ? out.torque_i : out.torque_j;
      const double *tj = first ? out.torque_j : out.torque_i;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      torque[i][0] += ti[0];
      torque[i][1] += ti[1];
      torque[i][2] += ti[2];
      if (j < nlocal) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
        torque[j][0] += tj[0];
        torque[j][1] += tj[1];
        torque[j][2] += tj[2];
      }
      if (evflag)
        ev_tally_xyz(i, j, nlocal, 0, 0.0, 0.0, fx, fy, fz, x[i][0] - x[j][0], x[i][1] - x[j][1],
                     x[i][2] - x[j][2]);
    }
  }
}

/* the contact between i and j as compute pair/local sees it: the stored history
   is read, not advanced; fforce * r is the normal force; the energy is not
   tallied (0); svector: normal force, tangential force, contact radius, F_n0 */
double PairTabor::single(int i, int j, int /*itype*/, int /*jtype*/, double rsq, double /*factor_coul*/,
                         double /*factor_lj*/, double &fforce)
{
  fforce = 0.0;
  for (int k = 0; k < single_extra; k++) svector[k] = 0.0;
  TaborContactForces out;
  int first;
  if (!evaluate(i, j, -1, out, first)) return 0.0;
  fforce = out.normal_force / sqrt(rsq);
  svector[0] = out.normal_force;
  svector[1] = out.tangential_force;
  svector[2] = out.contact_radius;
  svector[3] = out.critical_force;
  return 0.0;
}

double PairTabor::memory_usage()
{
  return (double) coeffs.size() * sizeof(Coeff);
}
