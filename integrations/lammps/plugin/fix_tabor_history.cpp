#include "fix_tabor_history.h"

#include "tabor_ffi.h"

#include "atom.h"
#include "tabor_coeff.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "neigh_list.h"
#include "utils.h"

#include <cmath>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

static constexpr int INITIAL_CAPACITY = 8;

/* fix ID group tabor/history WIDTH */
FixTaborHistory::FixTaborHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), dnum(0), capacity(INITIAL_CAPACITY), nmax_alloc(0), npartner(nullptr),
    partner(nullptr), values(nullptr), stamp(nullptr), pstamp(nullptr)
{
  if (narg != 4) error->all(FLERR, "Illegal fix tabor/history command (created by pair style tabor)");
  dnum = utils::inumeric(FLERR, arg[3], false, lmp);
  if (dnum < 1) error->all(FLERR, "fix tabor/history: width {} must be at least 1", dnum);
  create_attribute = 1;
  restart_peratom = 1;
  maxexchange_dynamic = 1;
  maxexchange = 2 + capacity * (2 + dnum);
  comm_forward = 1;    // the creation stamps of ghost atoms
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  // the atoms that exist now are their IDs' first incarnation here: stamp 0
  for (int i = 0; i < nmax_alloc; i++) {
    npartner[i] = 0;
    stamp[i] = 0.0;
  }
}

FixTaborHistory::~FixTaborHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->sfree(partner);
  memory->sfree(values);
  memory->destroy(stamp);
  memory->sfree(pstamp);
}

int FixTaborHistory::setmask()
{
  return 0;
}

void FixTaborHistory::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "tabor/history:npartner");
  partner = (tagint *) memory->srealloc(partner, sizeof(tagint) * (bigint) nmax * capacity,
                                        "tabor/history:partner");
  values = (double *) memory->srealloc(values, sizeof(double) * (bigint) nmax * capacity * dnum,
                                       "tabor/history:values");
  memory->grow(stamp, nmax, "tabor/history:stamp");
  pstamp = (double *) memory->srealloc(pstamp, sizeof(double) * (bigint) nmax * capacity,
                                       "tabor/history:pstamp");
  for (int i = nmax_alloc; i < nmax; i++) {
    npartner[i] = 0;
    stamp[i] = 0.0;
  }
  nmax_alloc = nmax;
}

void FixTaborHistory::grow_capacity()
{
  int wider = 2 * capacity;
  auto *p = (tagint *) memory->smalloc(sizeof(tagint) * (bigint) nmax_alloc * wider, "tabor/history:partner");
  auto *v = (double *) memory->smalloc(sizeof(double) * (bigint) nmax_alloc * wider * dnum, "tabor/history:values");
  auto *ps = (double *) memory->smalloc(sizeof(double) * (bigint) nmax_alloc * wider, "tabor/history:pstamp");
  for (int i = 0; i < nmax_alloc; i++) {
    int n = npartner[i] < capacity ? npartner[i] : capacity;
    if (n > 0) {
      memcpy(p + (bigint) i * wider, partner + (bigint) i * capacity, sizeof(tagint) * n);
      memcpy(ps + (bigint) i * wider, pstamp + (bigint) i * capacity, sizeof(double) * n);
      memcpy(v + (bigint) i * wider * dnum, values + (bigint) i * capacity * dnum, sizeof(double) * n * dnum);
    }
  }
  memory->sfree(partner);
  memory->sfree(values);
  memory->sfree(pstamp);
  partner = p;
  values = v;
  pstamp = ps;
  capacity = wider;
  maxexchange = 2 + capacity * (2 + dnum);
}

void FixTaborHistory::set_width(int wide)
{
  if (wide < 1) error->all(FLERR, "fix tabor/history: width {} must be at least 1", wide);
  if (wide == dnum) return;
  auto *v = (double *) memory->smalloc(sizeof(double) * (bigint) nmax_alloc * capacity * wide, "tabor/history:values");
  int keep = MIN(dnum, wide);
  for (int i = 0; i < nmax_alloc; i++)
    for (int k = 0; k < npartner[i] && k < capacity; k++) {
      double *to = v + ((bigint) i * capacity + k) * wide;
      const double *from = values + ((bigint) i * capacity + k) * dnum;
      memcpy(to, from, sizeof(double) * keep);
      for (int d = keep; d < wide; d++) to[d] = 0.0;
    }
  memory->sfree(values);
  values = v;
  dnum = wide;
  maxexchange = 2 + capacity * (2 + dnum);
}

void FixTaborHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  npartner[j] = npartner[i];
  stamp[j] = stamp[i];
  memcpy(partner + (bigint) j * capacity, partner + (bigint) i * capacity, sizeof(tagint) * npartner[i]);
  memcpy(pstamp + (bigint) j * capacity, pstamp + (bigint) i * capacity, sizeof(double) * npartner[i]);
  memcpy(values + (bigint) j * capacity * dnum, values + (bigint) i * capacity * dnum,
         sizeof(double) * npartner[i] * dnum);
}

/* a new atom (create_atoms, fix deposit, ...): no contact, and a creation stamp
   no atom of its ID had before, whatever ID it gets */
void FixTaborHistory::set_arrays(int i)
{
  npartner[i] = 0;
  stamp[i] = next_stamp + (double) issued * comm->nprocs + comm->me;
  issued_max = MAX(issued_max, stamp[i]);
  issued++;
}

/* the next stamps lie above every stamp an atom or a record holds, or that
   was ever issued (a deleted atom's too): all ranks agree on the base */
void FixTaborHistory::refresh_stamps()
{
  double most = issued_max;
  for (int i = 0; i < atom->nlocal; i++) {
    most = MAX(most, stamp[i]);
    const double *ps = pstamp + (bigint) i * capacity;
    for (int k = 0; k < npartner[i]; k++) most = MAX(most, ps[k]);
  }
  double all = 0.0;
  MPI_Allreduce(&most, &all, 1, MPI_DOUBLE, MPI_MAX, world);
  next_stamp = all + 1.0;
  issued = 0;
}

/* drops the records whose partner is not a neighbor (list: pair tabor's
   newton-off half list, just rebuilt): a contact's partner is always within
   the list's reach, so such a record belongs to a deleted atom */
void FixTaborHistory::drop_orphans(int inum, const int *ilist, const int *numneigh, int *const *firstneigh)
{
  const tagint *tag = atom->tag;
  int nlocal = atom->nlocal;
  std::vector<char> seen((size_t) nlocal * capacity, 0);
  auto mark = [&](int i, int j) {
    const tagint *p = partner + (bigint) i * capacity;
    const double *ps = pstamp + (bigint) i * capacity;
    for (int k = 0; k < npartner[i]; k++)
      if (p[k] == tag[j] && ps[k] == stamp[j]) seen[(size_t) i * capacity + k] = 1;
  };
  for (int ii = 0; ii < inum; ii++) {
    int i = ilist[ii];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      int j = firstneigh[i][jj] & NEIGHMASK;
      if (npartner[i]) mark(i, j);
      if (j < nlocal && npartner[j]) mark(j, i);
    }
  }
  for (int i = 0; i < nlocal; i++) {
    for (int k = npartner[i] - 1; k >= 0; k--)
      if (!seen[(size_t) i * capacity + k]) remove(i, k);
  }
}

void FixTaborHistory::remove(int i, int k)
{
  tagint *p = partner + (bigint) i * capacity;
  double *ps = pstamp + (bigint) i * capacity;
  double *v = values + (bigint) i * capacity * dnum;
  int last = --npartner[i];
  p[k] = p[last];
  ps[k] = ps[last];
  if (k != last) memmove(v + k * dnum, v + last * dnum, sizeof(double) * dnum);
}

int FixTaborHistory::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  for (int k = 0; k < n; k++) buf[k] = stamp[list[k]];
  return n;
}

void FixTaborHistory::unpack_forward_comm(int n, int first, double *buf)
{
  for (int k = 0; k < n; k++) stamp[first + k] = buf[k];
}

int FixTaborHistory::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  buf[m++] = stamp[i];
  const tagint *p = partner + (bigint) i * capacity;
  const double *ps = pstamp + (bigint) i * capacity;
  const double *v = values + (bigint) i * capacity * dnum;
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(p[k]).d;
    buf[m++] = ps[k];
    for (int d = 0; d < dnum; d++) buf[m++] = v[k * dnum + d];
  }
  return m;
}

int FixTaborHistory::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  int n = static_cast<int>(buf[m++]);
  while (n > capacity) grow_capacity();
  npartner[nlocal] = n;
  stamp[nlocal] = buf[m++];
  tagint *p = partner + (bigint) nlocal * capacity;
  double *ps = pstamp + (bigint) nlocal * capacity;
  double *v = values + (bigint) nlocal * capacity * dnum;
  for (int k = 0; k < n; k++) {
    p[k] = (tagint) ubuf(buf[m++]).i;
    ps[k] = buf[m++];
    for (int d = 0; d < dnum; d++) v[k * dnum + d] = buf[m++];
  }
  return m;
}

/* restart layout per atom: [size, -1, npartner, stamp, (tag, partner stamp,
   dnum values) * npartner]; buf[0] counts every value including itself
   (LAMMPS's convention); -1 marks the layout with creation stamps (the records
   of earlier builds, [size, npartner, (tag, values) * npartner], read with every
   stamp 0: their atoms are their IDs' first incarnation) */
int FixTaborHistory::pack_restart(int i, double *buf)
{
  buf[1] = -1.0;
  int m = 2;
  m += pack_exchange(i, &buf[2]);
  buf[0] = m;
  return m;
}

/* A record written by another build may hold another number of doubles per
   contact. The layout of TaborContactHistory: the contact flag and turning point
   of the normal law (2), the tangential and rolling displacements, the contact
   radius of mindlin_rescale and the twist angle (8 more: 10 in all, what every
   model but mindlin_deresiewicz uses), then the micro-slip bed of
   mindlin_deresiewicz (TABOR_MICRO_SLIP_LEN more). Fewer doubles than this
   build keeps: the missing ones start at zero (an older model's contact, or a
   contact without micro-slip). More: accepted when the values dropped are all
   zero (a contact that did not use them), refused otherwise. A record of 16
   doubles per contact with values beyond the 10th is Thornton's incremental
   micro-slip state of builds before the spring bed, which this build cannot
   continue: refused. */
void FixTaborHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  npartner[nlocal] = 0;
  // every number of the record is checked before it is used: a corrupted record
  // is refused (check_restart, on every rank), never read out of bounds
  const tagint self = atom->tag[nlocal];
  auto refuse = [&](const std::string &what) {
    if (bad_record.empty())
      bad_record = fmt::format("fix tabor/history: the restart record of atom {} {}", self, what);
  };
  std::string before;
  int m = tabor_restart_offset(lmp, nlocal, nth, before);
  if (m < 0) return refuse(before);
  const double *rec = &extra[nlocal][m];
  const double room = atom->nextra_store > m ? atom->nextra_store - m : 0;
  double size_d = rec[0];
  if (!std::isfinite(size_d) || size_d != std::floor(size_d) || size_d < 2 || (room > 0 && size_d > room))
    return refuse(fmt::format("has a length of {} values (2 to {} expected): a corrupted restart file", size_d,
                              room));
  int size = static_cast<int>(size_d);
  // the layout: with creation stamps (-1 after the length), or of earlier builds
  const bool stamped = size >= 4 && rec[1] == -1.0;
  const int head = stamped ? 4 : 2, per = stamped ? 2 : 1;
  // the partner count: [length, -1, count, stamp, ...] or [length, count, ...]
  double n_d = stamped ? rec[2] : rec[1];
  if (!std::isfinite(n_d) || n_d != std::floor(n_d) || n_d < 0 || n_d > (size - head) / (per + 1))
    return refuse(fmt::format("has a partner count of {} (0 to {} fit in its {} values): a corrupted restart file",
                              n_d, (size - head) / (per + 1), size));
  int n = static_cast<int>(n_d);
  if (n == 0 && size != head)
    return refuse(fmt::format("holds no contact but {} values: a corrupted restart file", size));
  int stored = n > 0 ? (size - head) / n - per : dnum;
  if (n > 0 && (size - head) != n * (per + stored))
    return refuse(fmt::format("of {} values cannot hold {} contacts: a corrupted restart file", size, n));
  auto whole = [](double x) { return std::isfinite(x) && x >= 0.0 && x == std::floor(x) && x < 9007199254740992.0; };
  double own = stamped ? rec[3] : 0.0;
  if (!whole(own)) return refuse(fmt::format("has the creation stamp {} (a whole number >= 0)", own));
  const double *entry = &rec[head];
  for (int k = 0; k < n; k++, entry += per + stored) {
    tagint t = (tagint) ubuf(entry[0]).i;
    if (t <= 0 || t == self)
      return refuse(fmt::format("has partner ID {} (contact {} of {}): an ID is > 0 and not the atom's own", t,
                                k + 1, n));
    if (stamped && !whole(entry[1]))
      return refuse(fmt::format("has the partner stamp {} for atom {} (a whole number >= 0)", entry[1], t));
    const double *h = entry + per;
    for (int d = 0; d < stored; d++)
      if (!std::isfinite(h[d]))
        return refuse(fmt::format("has the non-finite value {} (double {} of its contact with atom {})", h[d], d,
                                  t));
    if (h[0] != 1.0)
      return refuse(fmt::format("has contact flag {} with atom {} (a stored contact has 1)", h[0], t));
    std::string bad = tabor_history_problem(h, MIN(stored, dnum));
    if (!bad.empty()) return refuse(fmt::format("holds {} for its contact with atom {}", bad, t));
  }
  // an older model's contact: the dropped doubles must be zero
  entry = &rec[head];
  for (int k = 0; k < n; k++, entry += per + stored) {
    TaborHistoryFit fit = tabor_history_fit(entry + per, stored, dnum);
    if (fit != TABOR_HISTORY_FITS) {
      if (bad_record.empty())
        bad_record = fit == TABOR_HISTORY_THORNTON
            ? std::string("fix tabor/history: the restart file holds the micro-slip state of Thornton's "
                          "incremental form (16 doubles per contact), which this build of pair tabor replaced by "
                          "a spring bed; restart that run from its data file")
            : fmt::format("fix tabor/history: the restart file holds {} doubles per contact, this build of pair "
                          "tabor keeps {} for these pair coefficients and cannot drop the rest (a micro-slip bed, "
                          "or a newer tabor's state)",
                          stored, dnum);
      return;
    }
  }
  while (n > capacity) grow_capacity();
  npartner[nlocal] = n;
  stamp[nlocal] = own;
  tagint *p = partner + (bigint) nlocal * capacity;
  double *ps = pstamp + (bigint) nlocal * capacity;
  double *v = values + (bigint) nlocal * capacity * dnum;
  entry = &rec[head];
  for (int k = 0; k < n; k++, entry += per + stored) {
    p[k] = (tagint) ubuf(entry[0]).i;
    ps[k] = stamped ? entry[1] : 0.0;
    for (int d = 0; d < dnum; d++) v[k * dnum + d] = d < stored ? entry[per + d] : 0.0;
  }
}

int FixTaborHistory::size_restart(int i)
{
  return 4 + npartner[i] * (2 + dnum);
}

int FixTaborHistory::maxsize_restart()
{
  int most = 0;
  for (int i = 0; i < atom->nlocal; i++) most = MAX(most, npartner[i]);
  int all = 0;
  MPI_Allreduce(&most, &all, 1, MPI_INT, MPI_MAX, world);
  return 4 + all * (2 + dnum);
}

double FixTaborHistory::memory_usage()
{
  return (double) nmax_alloc * (sizeof(int) + sizeof(double) + capacity * (sizeof(tagint) + sizeof(double) * (1 + dnum)));
}

double *FixTaborHistory::find(int i, tagint t, double st)
{
  const tagint *p = partner + (bigint) i * capacity;
  const double *ps = pstamp + (bigint) i * capacity;
  for (int k = 0; k < npartner[i]; k++)
    if (p[k] == t) {
      if (ps[k] == st) return values + ((bigint) i * capacity + k) * dnum;
      // the record of a deleted atom whose ID came back: it dies here
      remove(i, k);
      return nullptr;
    }
  return nullptr;
}

void FixTaborHistory::store(int i, tagint t, double st, const double *h)
{
  tagint *p = partner + (bigint) i * capacity;
  double *v = values + (bigint) i * capacity * dnum;
  for (int k = 0; k < npartner[i]; k++) {
    if (p[k] == t) {
      if (h[0] != 0.0) {
        if (v + k * dnum != h) memcpy(v + k * dnum, h, sizeof(double) * dnum);
        pstamp[(bigint) i * capacity + k] = st;
      } else {
        remove(i, k);
      }
      return;
    }
  }
  if (h[0] == 0.0) return;
  if (npartner[i] >= capacity) {
    grow_capacity();
    p = partner + (bigint) i * capacity;
    v = values + (bigint) i * capacity * dnum;
  }
  p[npartner[i]] = t;
  pstamp[(bigint) i * capacity + npartner[i]] = st;
  memcpy(v + npartner[i] * dnum, h, sizeof(double) * dnum);
  npartner[i]++;
}

/* A record refused by unpack_restart (on the rank that owns the atom) becomes
   one error->all on every rank, with the message of the lowest such rank. */
void FixTaborHistory::check_restart()
{
  tabor_raise_first(lmp, bad_record);
}
