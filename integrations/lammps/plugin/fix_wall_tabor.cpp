#include "fix_wall_tabor.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "region.h"
#include "tabor_coeff.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

static constexpr int HLEN = TABOR_CONTACT_HISTORY_LEN;
static constexpr int HBASE = TABOR_CONTACT_HISTORY_BASE_LEN;
static constexpr double BIG = 1.0e20;
// the per-atom output of `contacts`: touching flag, force (3), torque (3), contact radius
static constexpr int NCOLS = 8;

/* fix ID group wall/tabor MODEL ARGS [KEYWORDS] wallstyle args [wiggle|shear|contacts ...]
   fix ID group wall/tabor/region MODEL ARGS [KEYWORDS] regionID [contacts] */
FixWallTabor::FixWallTabor(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), contact(nullptr), rmax_seen(0.0), reach_max(0.0), wallstyle(ZPLANE), lo(-BIG), hi(BIG),
    cylradius(0.0), wiggle(0), wshear(0), axis(0), amplitude(0.0), period(0.0), omega_wiggle(0.0),
    vshear(0.0), time_origin(0), region(nullptr), nslot(1), hlen(HBASE), ncontact(nullptr), walls(nullptr),
    history(nullptr), nmax_alloc(0)
{
  memset(&scratch, 0, sizeof(scratch));
  bool is_region = strcmp(style, "wall/tabor/region") == 0;
  who = is_region ? "fix wall/tabor/region" : "fix wall/tabor";
  if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
    error->all(FLERR, "{} requires atom attributes radius, rmass, omega, torque (atom_style sphere)", who);

  TaborCoeff coeff;
  int iarg;
  if (is_region) {
    // the region ID follows the coefficients; `contacts` may follow it
    int last = narg;
    if (last > 4 && strcmp(arg[last - 1], "contacts") == 0) {
      peratom_flag = 1;
      last--;
    }
    if (last < 5) error->all(FLERR, "Illegal {} command: fix ID group {} MODEL ARGS [KEYWORDS] regionID", who, style);
    iarg = tabor_parse_coeff(lmp, who, last - 1, arg, 3, {}, coeff);
    idregion = arg[last - 1];
    region = domain->get_region_by_id(idregion);
    if (!region) error->all(FLERR, "{}: region {} does not exist", who, idregion);
    wallstyle = REGION;
    nslot = region->tmax;
    if (nslot < 1) error->all(FLERR, "{}: region {} has no surface to touch (tmax {})", who, idregion, nslot);
    iarg = narg;
  } else {
    iarg = tabor_parse_coeff(lmp, who, narg, arg, 3, {"xplane", "yplane", "zplane", "zcylinder"}, coeff);
    if (iarg >= narg)
      error->all(FLERR, "{}: missing the wallstyle (xplane|yplane|zplane lo hi, or zcylinder radius)", who);
    std::string ws = arg[iarg++];
    auto bound = [&](const char *name, double none) {
      if (iarg >= narg) error->all(FLERR, "{} {}: missing {}", who, ws, name);
      if (strcmp(arg[iarg], "NULL") == 0) {
        iarg++;
        return none;
      }
      return utils::numeric(FLERR, arg[iarg++], false, lmp);
    };
    if (ws == "zcylinder") {
      wallstyle = ZCYLINDER;
      if (iarg >= narg) error->all(FLERR, "{} zcylinder: missing the radius", who);
      cylradius = utils::numeric(FLERR, arg[iarg++], false, lmp);
      if (!(cylradius > 0.0)) error->all(FLERR, "{}: zcylinder radius {} must be > 0", who, cylradius);
    } else {
      wallstyle = ws == "xplane" ? XPLANE : ws == "yplane" ? YPLANE : ZPLANE;
      lo = bound("lo", -BIG);
      hi = bound("hi", BIG);
      if (lo == -BIG && hi == BIG) error->all(FLERR, "{} {}: lo and hi cannot both be NULL", who, ws);
      if (!(lo < hi)) error->all(FLERR, "{} {}: lo {} must be below hi {}", who, ws, lo, hi);
    }
    auto dim = [&](const char *key) {
      if (iarg >= narg) error->all(FLERR, "{} {}: missing the dimension (x, y or z)", who, key);
      std::string d = arg[iarg++];
      if (d == "x") return 0;
      if (d == "y") return 1;
      if (d == "z") return 2;
      error->all(FLERR, "{} {}: dimension {} is not x, y or z", who, key, d);
      return -1;
    };
    while (iarg < narg) {
      std::string key = arg[iarg++];
      if (key == "wiggle") {
        axis = dim("wiggle");
        if (iarg + 2 > narg) error->all(FLERR, "{} wiggle: dim amplitude period", who);
        amplitude = utils::numeric(FLERR, arg[iarg++], false, lmp);
        period = utils::numeric(FLERR, arg[iarg++], false, lmp);
        if (!(period > 0.0)) error->all(FLERR, "{} wiggle: period {} must be > 0", who, period);
        wiggle = 1;
      } else if (key == "shear") {
        axis = dim("shear");
        if (iarg >= narg) error->all(FLERR, "{} shear: dim vshear", who);
        vshear = utils::numeric(FLERR, arg[iarg++], false, lmp);
        wshear = 1;
      } else if (key == "contacts") {
        peratom_flag = 1;
      } else {
        error->all(FLERR, "{}: unknown keyword {} (wiggle, shear, contacts)", who, key);
      }
    }
    const int periodic[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
    if (wallstyle <= ZPLANE && periodic[wallstyle])
      error->all(FLERR, "{}: cannot use a wall in a periodic dimension ({})", who, ws);
    if (wallstyle == ZCYLINDER && (periodic[0] || periodic[1]))
      error->all(FLERR, "{}: cannot use zcylinder with x or y periodic", who);
    if (wiggle && wshear) error->all(FLERR, "{}: cannot both wiggle and shear", who);
    if (wiggle && wallstyle == ZCYLINDER && axis != 2)
      error->all(FLERR, "{}: a zcylinder wiggles only along z", who);
    if (wshear && wallstyle <= ZPLANE && axis == wallstyle)
      error->all(FLERR, "{}: shear along the wall's normal ({}) is not a shear", who, ws);
    if (wiggle) omega_wiggle = 2.0 * M_PI / period;
  }
  (void) iarg;

  int status = tabor_contact_new(&coeff.params, &coeff.friction, &contact);
  if (status != TABOR_OK) tabor_fail_all(lmp, who, status, "coefficients");
  // the doubles a contact keeps: the micro-slip bed only with mindlin_deresiewicz
  hlen = static_cast<int>(tabor_contact_history_len(contact));
  if (hlen != HBASE && hlen != HLEN)
    error->all(FLERR, "{}: tabor_contact_history_len {} is neither {} nor {}", who, hlen, HBASE, HLEN);

  if (peratom_flag) {
    size_peratom_cols = NCOLS;
    peratom_freq = 1;
  }
  create_attribute = 1;
  restart_peratom = 1;
  maxexchange = 1 + nslot * (1 + hlen) + (peratom_flag ? NCOLS : 0);
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < nmax_alloc; i++) set_arrays(i);
  time_origin = update->ntimestep;
}

FixWallTabor::~FixWallTabor()
{
  if (copymode) return;
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  tabor_contact_free(contact);
  memory->destroy(ncontact);
  memory->sfree(walls);
  memory->sfree(history);
  memory->destroy(array_atom);
}

int FixWallTabor::setmask()
{
  return POST_FORCE;
}

void FixWallTabor::init()
{
  check_restart();
  // every atom of the group finite, with a radius and mass > 0 (error->all)
  tabor_check_atoms(lmp, who, groupbit);
  if (wallstyle == REGION) {
    Region *now = domain->get_region_by_id(idregion);
    if (!now) error->all(FLERR, "{}: region {} does not exist", who, idregion);
    if (now != region || now->tmax != nslot)
      error->all(FLERR, "{}: region {} was redefined since the fix was created; unfix and fix again", who,
                 idregion);
  }
  // the reach over the group's radii, from the law itself (tabor_contact_prepare:
  // with `maugis ... range h` each radius has its own Lambda, so lengths do not
  // scale as R^(1/3) from one radius; it also builds that law's table nodes now)
  double *radius = atom->radius;
  int *mask = atom->mask;
  double rlo = BIG, rhi = 0.0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && radius[i] > 0.0) {
      rlo = MIN(rlo, radius[i]);
      rhi = MAX(rhi, radius[i]);
    }
  double rmin = BIG, rmax = 0.0;
  MPI_Allreduce(&rlo, &rmin, 1, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&rhi, &rmax, 1, MPI_DOUBLE, MPI_MAX, world);
  if (rmax > 0.0) {
    double reach = 0.0;
    int status = tabor_contact_prepare(contact, rmin, rmax, &reach);
    if (status != TABOR_OK) tabor_fail_all(lmp, who, status, "tabor_contact_prepare");
    rmax_seen = MAX(rmax_seen, rmax);
    reach_max = MAX(reach_max, reach);
  }
}

/* a particle larger than any met so far: the reach bound grows to the law's reach
   at its radius (the bound is the largest reach of every radius met) */
void FixWallTabor::grow_reach(double r)
{
  double reach = 0.0;
  int status = tabor_contact_prepare(contact, r, r, &reach);
  if (status != TABOR_OK) tabor_fail_rank(lmp, FLERR, "{}: tabor_contact_prepare at radius {} failed (status {})", who, r, status);
  rmax_seen = r;
  reach_max = MAX(reach_max, reach);
}

void FixWallTabor::setup(int vflag)
{
  post_force(vflag);
}

void FixWallTabor::reset_dt() {}

/* the stored history of atom i with wall `wall`, added (zeroed) when absent */
double *FixWallTabor::find_or_add(int i, int wall)
{
  int *w = walls + (bigint) i * nslot;
  for (int k = 0; k < ncontact[i]; k++)
    if (w[k] == wall) return history_of(i, k);
  if (ncontact[i] >= nslot)
    tabor_fail_rank(lmp, FLERR, "{}: atom {} touches more than {} walls at once", who, atom->tag[i], nslot);
  int k = ncontact[i]++;
  w[k] = wall;
  double *h = history_of(i, k);
  for (int d = 0; d < hlen; d++) h[d] = 0.0;
  return h;
}

void FixWallTabor::forget(int i, int wall)
{
  int *w = walls + (bigint) i * nslot;
  for (int k = 0; k < ncontact[i]; k++)
    if (w[k] == wall) {
      int last = --ncontact[i];
      if (k != last) {
        w[k] = w[last];
        memcpy(history_of(i, k), history_of(i, last), sizeof(double) * hlen);
      }
      return;
    }
}

/* one contact of atom i with wall `wall`: del is the vector from the wall's
   nearest point to the particle's centre, vwall the wall's velocity there */
void FixWallTabor::one_contact(int i, int wall, const double *del, const double *vwall, double **out_rows)
{
  double *radius = atom->radius;
  double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
  double ri = radius[i];
  // a stored contact is found whatever the gap; a new one only within reach: the
  // largest reach of every radius met (grow_reach) bounds every atom's, so no
  // law call per atom and step; the law itself tells an atom between its own
  // reach and the bound that it has no contact
  int *w = walls + (bigint) i * nslot;
  bool stored = false;
  for (int k = 0; k < ncontact[i]; k++) stored = stored || w[k] == wall;
  if (!stored) {
    if (ri > rmax_seen) grow_reach(ri);
    double cut = ri + reach_max;
    if (rsq >= cut * cut) return;
  }
  double r = sqrt(rsq);
  if (r == 0.0) {
    if (update->setupflag) {
      centre_on_wall = MIN(centre_on_wall, atom->tag[i]);
      return;
    }
    tabor_fail_rank(lmp, FLERR, "{}: the centre of atom {} lies on the wall", who, atom->tag[i]);
  }
  double rinv = 1.0 / r;
  double **v = atom->v;
  double **omega = atom->omega;
  TaborContactState s;
  for (int k = 0; k < 3; k++) {
    s.normal[k] = del[k] * rinv;
    s.relative_velocity[k] = v[i][k] - vwall[k];
    s.angular_velocity_i[k] = omega[i][k];
    s.angular_velocity_j[k] = 0.0;
  }
  s.overlap = ri - r;
  s.radius_i = ri;
  s.radius_j = INFINITY;    // a flat wall: R* = R_i, torque arm R_i
  s.time_step = update->dt;
  s.effective_mass = atom->rmass[i];
  s.update_history = update->setupflag ? 0 : 1;
  // the stored doubles are the leading hlen of a TaborContactHistory (repr(C), all
  // doubles): the full width (the micro-slip bed) is stepped where it lies, a
  // narrower one in the scratch copy whose bed stays zero; tabor_contact_step
  // leaves the history unchanged on error
  static_assert(sizeof(TaborContactHistory) == HLEN * sizeof(double), "history layout");
  double *h = find_or_add(i, wall);
  TaborContactHistory *hp = &scratch;
  if (hlen == HLEN)
    hp = reinterpret_cast<TaborContactHistory *>(h);
  else
    memcpy(&scratch, h, sizeof(double) * hlen);
  TaborContactHistory &hist = *hp;
  TaborContactForces out;
  int status = tabor_contact_step(contact, &s, hp, &out);
  if (hlen != HLEN) memcpy(h, &scratch, sizeof(double) * hlen);
  if (status != TABOR_OK) {
    char buf[512];
    tabor_last_error(buf, sizeof(buf));
    tabor_fail_rank(lmp, FLERR, "{}: tabor_contact_step (status {}) for atom {}: {}", who, status, atom->tag[i], buf);
  }
  if (hist.contact == 0.0) {
    forget(i, wall);
    return;
  }
  double **f = atom->f;
  double **torque = atom->torque;
  for (int k = 0; k < 3; k++) {
    f[i][k] += out.force[k];
    torque[i][k] += out.torque_i[k];
  }
  if (out_rows) {
    double *row = out_rows[i];
    row[0] = 1.0;
    for (int k = 0; k < 3; k++) {
      row[1 + k] += out.force[k];
      row[4 + k] += out.torque_i[k];
    }
    row[7] = MAX(row[7], out.contact_radius);
  }
}

/* the contacts of every atom of the group; at setup (the first force call of a
   run, on every rank) an atom whose centre lies on a wall, which has no contact
   normal, is refused with error->all (during the run only its rank meets it) */
void FixWallTabor::post_force(int /*vflag*/)
{
  centre_on_wall = MAXTAGINT;
  all_contacts();
  if (update->setupflag) {
    tagint worst = MAXTAGINT;
    MPI_Allreduce(&centre_on_wall, &worst, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (worst != MAXTAGINT)
      error->all(FLERR, "{}: the centre of atom {} lies on the wall (no contact normal): start it off the wall", who,
                 worst);
  }
}

void FixWallTabor::all_contacts()
{
  double **x = atom->x;
  int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (peratom_flag)
    for (int i = 0; i < nlocal; i++)
      for (int m = 0; m < NCOLS; m++) array_atom[i][m] = 0.0;
  double **rows = peratom_flag ? array_atom : nullptr;

  if (wallstyle == REGION) {
    int dynamic = region->dynamic_check();
    if (dynamic) {
      region->prematch();
      region->set_velocity();
    }
    double *radius = atom->radius;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit)) continue;
      if (!region->match(x[i][0], x[i][1], x[i][2])) {
        ncontact[i] = 0;
        continue;
      }
      if (radius[i] > rmax_seen) grow_reach(radius[i]);
      double cutoff = radius[i] + reach_max;
      int nc = region->surface(x[i][0], x[i][1], x[i][2], cutoff);
      if (nc > nslot) tabor_fail_rank(lmp, FLERR, "{}: atom {} touches {} surfaces of region {} (at most {})", who,
                                 atom->tag[i], nc, idregion, nslot);
      // a contact whose surface is no longer within reach has separated
      for (int k = ncontact[i] - 1; k >= 0; k--) {
        int wk = walls[(bigint) i * nslot + k];
        bool seen = false;
        for (int c = 0; c < nc; c++) seen = seen || region->contact[c].iwall == wk;
        if (!seen) forget(i, wk);
      }
      for (int c = 0; c < nc; c++) {
        double del[3] = {region->contact[c].delx, region->contact[c].dely, region->contact[c].delz};
        double vwall[3] = {0.0, 0.0, 0.0};
        if (dynamic) region->velocity_contact(vwall, x[i], c);
        one_contact(i, region->contact[c].iwall, del, vwall, rows);
      }
    }
    return;
  }

  double wlo = lo, whi = hi;
  double vwall[3] = {0.0, 0.0, 0.0};
  if (wiggle) {
    double phase = omega_wiggle * (update->ntimestep - time_origin) * update->dt;
    if (wallstyle == axis) {
      wlo = lo + amplitude - amplitude * cos(phase);
      whi = hi + amplitude - amplitude * cos(phase);
    }
    vwall[axis] = amplitude * omega_wiggle * sin(phase);
  } else if (wshear) {
    vwall[axis] = vshear;
  }
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double del[3] = {0.0, 0.0, 0.0};
    double vw[3] = {vwall[0], vwall[1], vwall[2]};
    int wall = 0;
    if (wallstyle <= ZPLANE) {
      // the nearer of the two walls (fix wall/gran's rule); wall 0 lo, 1 hi
      double below = x[i][wallstyle] - wlo, above = whi - x[i][wallstyle];
      if (below < above) {
        del[wallstyle] = below;
      } else {
        del[wallstyle] = -above;
        wall = 1;
      }
    } else {
      double rxy = sqrt(x[i][0] * x[i][0] + x[i][1] * x[i][1]);
      if (rxy == 0.0) {
        if (ncontact[i]) forget(i, 0);
        continue;    // on the axis: no nearest point (and far from the wall)
      }
      double scale = (rxy - cylradius) / rxy;
      del[0] = scale * x[i][0];
      del[1] = scale * x[i][1];
      if (wshear && axis != 2) {
        // a cylinder turning about z with surface speed vshear
        vw[0] = vshear * x[i][1] / rxy;
        vw[1] = -vshear * x[i][0] / rxy;
        vw[2] = 0.0;
      }
    }
    // a contact kept with the other wall of a plane pair has separated
    if (ncontact[i] && walls[(bigint) i * nslot] != wall) ncontact[i] = 0;
    one_contact(i, wall, del, vw, rows);
  }
}

void FixWallTabor::grow_arrays(int nmax)
{
  memory->grow(ncontact, nmax, "wall/tabor:ncontact");
  walls = (int *) memory->srealloc(walls, sizeof(int) * (bigint) nmax * nslot, "wall/tabor:walls");
  history = (double *) memory->srealloc(history, sizeof(double) * (bigint) nmax * nslot * hlen,
                                        "wall/tabor:history");
  if (peratom_flag) memory->grow(array_atom, nmax, NCOLS, "wall/tabor:array_atom");
  for (int i = nmax_alloc; i < nmax; i++) set_arrays(i);
  nmax_alloc = nmax;
}

void FixWallTabor::copy_arrays(int i, int j, int /*delflag*/)
{
  ncontact[j] = ncontact[i];
  memcpy(walls + (bigint) j * nslot, walls + (bigint) i * nslot, sizeof(int) * ncontact[i]);
  memcpy(history_of(j, 0), history_of(i, 0), sizeof(double) * hlen * ncontact[i]);
  if (peratom_flag)
    for (int m = 0; m < NCOLS; m++) array_atom[j][m] = array_atom[i][m];
}

void FixWallTabor::set_arrays(int i)
{
  ncontact[i] = 0;
  if (peratom_flag)
    for (int m = 0; m < NCOLS; m++) array_atom[i][m] = 0.0;
}

/* [ncontact, (wall, hlen doubles) * ncontact, (NCOLS outputs with contacts)] */
int FixWallTabor::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = ncontact[i];
  for (int k = 0; k < ncontact[i]; k++) {
    buf[m++] = walls[(bigint) i * nslot + k];
    const double *h = history_of(i, k);
    for (int d = 0; d < hlen; d++) buf[m++] = h[d];
  }
  if (peratom_flag)
    for (int c = 0; c < NCOLS; c++) buf[m++] = array_atom[i][c];
  return m;
}

int FixWallTabor::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  int n = static_cast<int>(buf[m++]);
  if (n > nslot) tabor_fail_rank(lmp, FLERR, "{}: an atom arrived with {} wall contacts (at most {})", who, n, nslot);
  ncontact[nlocal] = n;
  for (int k = 0; k < n; k++) {
    walls[(bigint) nlocal * nslot + k] = static_cast<int>(buf[m++]);
    double *h = history_of(nlocal, k);
    for (int d = 0; d < hlen; d++) h[d] = buf[m++];
  }
  if (peratom_flag)
    for (int c = 0; c < NCOLS; c++) array_atom[nlocal][c] = buf[m++];
  return m;
}

/* restart record per atom: [size, width, ncontact, (wall, width doubles) * ncontact];
   buf[0] counts every value including itself (LAMMPS's convention). The width is
   written so that a record of another width is read by fix tabor/history's rules
   for the pair histories: fewer doubles than this fix keeps (a contact without
   micro-slip, or an older build) start the rest at zero; more are accepted when
   the values dropped are all zero (a contact that did not use them) and refused
   otherwise (a micro-slip bed this fix's model cannot continue, or a newer
   tabor's state); a 16-double record with values beyond the 10th is Thornton's
   incremental micro-slip state of builds before the spring bed: refused. */
int FixWallTabor::pack_restart(int i, double *buf)
{
  int m = 1;
  buf[m++] = hlen;
  buf[m++] = ncontact[i];
  for (int k = 0; k < ncontact[i]; k++) {
    buf[m++] = walls[(bigint) i * nslot + k];
    const double *h = history_of(i, k);
    for (int d = 0; d < hlen; d++) buf[m++] = h[d];
  }
  buf[0] = m;
  return m;
}

void FixWallTabor::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  ncontact[nlocal] = 0;
  // every number of the record is checked before it is used: a corrupted record
  // is refused (check_restart, one error->all on every rank), never cast or read
  // out of bounds
  auto refuse = [&](const std::string &what) {
    if (bad_record.empty())
      bad_record = fmt::format("{}: the restart record of atom {} {}", who, atom->tag[nlocal], what);
  };
  std::string before;
  int m = tabor_restart_offset(lmp, nlocal, nth, before);
  if (m < 0) return refuse(before);
  const double *buf = &extra[nlocal][m];
  const double room = atom->nextra_store > m ? atom->nextra_store - m : 0;
  auto integer = [](double x, double lo, double hi) {
    return std::isfinite(x) && x == std::floor(x) && x >= lo && x <= hi;
  };
  if (!integer(buf[0], 3, room > 0 ? room : 1e9))
    return refuse(fmt::format("has a length of {} values: a corrupted restart file", buf[0]));
  if (!integer(buf[1], 1, 1e6) || !integer(buf[2], 0, nslot))
    return refuse(fmt::format("holds {} wall contacts of {} doubles (0 to {} contacts): a corrupted restart file",
                              buf[2], buf[1], nslot));
  int size = static_cast<int>(buf[0]);
  int width = static_cast<int>(buf[1]);
  int n = static_cast<int>(buf[2]);
  if (size != 3 + n * (1 + width))
    return refuse(fmt::format("of {} values cannot hold {} wall contacts of {} doubles", size, n, width));
  for (int k = 0, k0 = 3; k < n; k++, k0 += 1 + width) {
    if (!integer(buf[k0], 0, 1e9))
      return refuse(fmt::format("names wall {}: a corrupted restart file", buf[k0]));
    for (int d = 0; d < width; d++)
      if (!std::isfinite(buf[k0 + 1 + d]))
        return refuse(fmt::format("holds the non-finite history value {} (contact {}, double {}): a corrupted "
                                  "restart file", buf[k0 + 1 + d], k, d));
    std::string bad = tabor_history_problem(buf + k0 + 1, MIN(width, hlen));
    if (!bad.empty()) return refuse(fmt::format("holds {} (contact {}): a corrupted restart file", bad, k));
  }
  // an older model's contact: the dropped doubles must be zero
  for (int k = 0, k0 = 3; k < n; k++, k0 += 1 + width) {
    TaborHistoryFit fit = tabor_history_fit(buf + k0 + 1, width, hlen);
    if (fit == TABOR_HISTORY_THORNTON)
      return refuse("holds the micro-slip state of Thornton's incremental form (16 doubles per wall "
                    "contact), which this build replaced by a spring bed; restart that run from its data file");
    if (fit == TABOR_HISTORY_DROPPED)
      return refuse(fmt::format("holds {} doubles per wall contact, this fix keeps {} for its model and cannot "
                                "drop the rest (a micro-slip bed of tangential mindlin_deresiewicz, or a newer "
                                "tabor's state)", width, hlen));
  }
  ncontact[nlocal] = n;
  int k0 = 3;
  for (int k = 0; k < n; k++) {
    walls[(bigint) nlocal * nslot + k] = static_cast<int>(buf[k0++]);
    double *h = history_of(nlocal, k);
    for (int d = 0; d < hlen; d++) h[d] = d < width ? buf[k0 + d] : 0.0;
    k0 += width;
  }
}

/* A record refused by unpack_restart (on the rank that owns the atom) becomes
   one error->all on every rank, with the message of the lowest such rank. */
void FixWallTabor::check_restart()
{
  tabor_raise_first(lmp, bad_record);
}

int FixWallTabor::size_restart(int i)
{
  return 3 + ncontact[i] * (1 + hlen);
}

int FixWallTabor::maxsize_restart()
{
  return 3 + nslot * (1 + hlen);
}

double FixWallTabor::memory_usage()
{
  double bytes = (double) nmax_alloc * (sizeof(int) + nslot * (sizeof(int) + sizeof(double) * hlen));
  if (peratom_flag) bytes += (double) nmax_alloc * NCOLS * sizeof(double);
  return bytes;
}
