#include "fix_tabor_history.h"

#include "tabor_ffi.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"
#include "utils.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

static constexpr int INITIAL_CAPACITY = 8;

/* fix ID group tabor/history WIDTH */
FixTaborHistory::FixTaborHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), dnum(0), capacity(INITIAL_CAPACITY), nmax_alloc(0), npartner(nullptr),
    partner(nullptr), values(nullptr)
{
  if (narg != 4) error->all(FLERR, "Illegal fix tabor/history command (created by pair style tabor)");
  dnum = utils::inumeric(FLERR, arg[3], false, lmp);
  if (dnum < 1) error->all(FLERR, "fix tabor/history: width {} must be at least 1", dnum);
  create_attribute = 1;
  restart_peratom = 1;
  maxexchange_dynamic = 1;
  maxexchange = 1 + capacity * (1 + dnum);
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < nmax_alloc; i++) npartner[i] = 0;
}

FixTaborHistory::~FixTaborHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->sfree(partner);
  memory->sfree(values);
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
  for (int i = nmax_alloc; i < nmax; i++) npartner[i] = 0;
  nmax_alloc = nmax;
}

void FixTaborHistory::grow_capacity()
{
  int wider = 2 * capacity;
  auto *p = (tagint *) memory->smalloc(sizeof(tagint) * (bigint) nmax_alloc * wider, "tabor/history:partner");
  auto *v = (double *) memory->smalloc(sizeof(double) * (bigint) nmax_alloc * wider * dnum, "tabor/history:values");
  for (int i = 0; i < nmax_alloc; i++) {
    int n = npartner[i] < capacity ? npartner[i] : capacity;
    if (n > 0) {
      memcpy(p + (bigint) i * wider, partner + (bigint) i * capacity, sizeof(tagint) * n);
      memcpy(v + (bigint) i * wider * dnum, values + (bigint) i * capacity * dnum, sizeof(double) * n * dnum);
    }
  }
  memory->sfree(partner);
  memory->sfree(values);
  partner = p;
  values = v;
  capacity = wider;
  maxexchange = 1 + capacity * (1 + dnum);
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
  maxexchange = 1 + capacity * (1 + dnum);
}

void FixTaborHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  npartner[j] = npartner[i];
  memcpy(partner + (bigint) j * capacity, partner + (bigint) i * capacity, sizeof(tagint) * npartner[i]);
  memcpy(values + (bigint) j * capacity * dnum, values + (bigint) i * capacity * dnum,
         sizeof(double) * npartner[i] * dnum);
}

void FixTaborHistory::set_arrays(int i)
{
  npartner[i] = 0;
}

int FixTaborHistory::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  const tagint *p = partner + (bigint) i * capacity;
  const double *v = values + (bigint) i * capacity * dnum;
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(p[k]).d;
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
  tagint *p = partner + (bigint) nlocal * capacity;
  double *v = values + (bigint) nlocal * capacity * dnum;
  for (int k = 0; k < n; k++) {
    p[k] = (tagint) ubuf(buf[m++]).i;
    for (int d = 0; d < dnum; d++) v[k * dnum + d] = buf[m++];
  }
  return m;
}

/* restart layout per atom: [size, npartner, (tag, dnum values) * npartner];
   buf[0] counts every value including itself (LAMMPS's convention) */
int FixTaborHistory::pack_restart(int i, double *buf)
{
  int m = 1;
  m += pack_exchange(i, &buf[1]);
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
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  npartner[nlocal] = 0;
  // every number of the record is checked before it is used: a corrupted record
  // is refused (check_restart, on every rank), never read out of bounds
  const double *rec = &extra[nlocal][m];
  const tagint self = atom->tag[nlocal];
  const double room = atom->nextra_store > m ? atom->nextra_store - m : 0;
  auto refuse = [&](const std::string &what) {
    if (bad_record.empty())
      bad_record = fmt::format("fix tabor/history: the restart record of atom {} {}", self, what);
  };
  double size_d = rec[0];
  if (!std::isfinite(size_d) || size_d != std::floor(size_d) || size_d < 2 || (room > 0 && size_d > room))
    return refuse(fmt::format("has a length of {} values (2 to {} expected): a corrupted restart file", size_d,
                              room));
  int size = static_cast<int>(size_d);
  const double *buf = &rec[1];
  double n_d = buf[0];
  if (!std::isfinite(n_d) || n_d != std::floor(n_d) || n_d < 0 || n_d > (size - 2) / 2)
    return refuse(fmt::format("has a partner count of {} (0 to {} fit in its {} values): a corrupted restart file",
                              n_d, (size - 2) / 2, size));
  int n = static_cast<int>(n_d);
  if (n == 0 && size != 2)
    return refuse(fmt::format("holds no contact but {} values: a corrupted restart file", size));
  int stored = n > 0 ? (size - 2) / n - 1 : dnum;
  if (n > 0 && (size - 2) != n * (1 + stored))
    return refuse(fmt::format("of {} values cannot hold {} contacts: a corrupted restart file", size, n));
  for (int k = 0, k0 = 1; k < n; k++, k0 += 1 + stored) {
    tagint t = (tagint) ubuf(buf[k0]).i;
    if (t <= 0 || t == self)
      return refuse(fmt::format("has partner ID {} (contact {} of {}): an ID is > 0 and not the atom's own", t,
                                k + 1, n));
    for (int d = 0; d < stored; d++)
      if (!std::isfinite(buf[k0 + 1 + d]))
        return refuse(fmt::format("has the non-finite value {} (double {} of its contact with atom {})",
                                  buf[k0 + 1 + d], d, t));
    if (buf[k0 + 1] != 1.0)
      return refuse(fmt::format("has contact flag {} with atom {} (a stored contact has 1)", buf[k0 + 1], t));
  }
  if (stored == dnum) {
    unpack_exchange(nlocal, const_cast<double *>(buf));
    return;
  }
  // Thornton's incremental state (builds before the spring bed): doubles 10-15
  int thornton = stored == 16 && TABOR_CONTACT_HISTORY_LEN != 16;
  for (int k = 0, k0 = 1; k < n; k++, k0 += 1 + stored)
    for (int d = thornton ? TABOR_CONTACT_HISTORY_BASE_LEN : dnum; d < stored; d++)
      if (buf[k0 + 1 + d] != 0.0) {
        if (bad_record.empty())
          bad_record = thornton
              ? std::string("fix tabor/history: the restart file holds the micro-slip state of Thornton's "
                            "incremental form (16 doubles per contact), which this build of pair tabor replaced by "
                            "a spring bed; restart that run from its data file")
              : fmt::format("fix tabor/history: the restart file holds {} doubles per contact, this build of pair "
                            "tabor keeps {} for these pair coefficients and cannot drop the rest (a micro-slip bed, "
                            "or a newer tabor's state)",
                            stored, dnum);
        return;
      }
  while (n > capacity) grow_capacity();
  npartner[nlocal] = n;
  tagint *p = partner + (bigint) nlocal * capacity;
  double *v = values + (bigint) nlocal * capacity * dnum;
  int k0 = 1;
  for (int k = 0; k < n; k++) {
    p[k] = (tagint) ubuf(buf[k0++]).i;
    for (int d = 0; d < dnum; d++) v[k * dnum + d] = d < stored ? buf[k0 + d] : 0.0;
    k0 += stored;
  }
}

int FixTaborHistory::size_restart(int i)
{
  return 2 + npartner[i] * (1 + dnum);
}

int FixTaborHistory::maxsize_restart()
{
  int most = 0;
  for (int i = 0; i < atom->nlocal; i++) most = MAX(most, npartner[i]);
  int all = 0;
  MPI_Allreduce(&most, &all, 1, MPI_INT, MPI_MAX, world);
  return 2 + all * (1 + dnum);
}

double FixTaborHistory::memory_usage()
{
  return (double) nmax_alloc * (sizeof(int) + capacity * (sizeof(tagint) + sizeof(double) * dnum));
}

double *FixTaborHistory::find(int i, tagint t)
{
  const tagint *p = partner + (bigint) i * capacity;
  for (int k = 0; k < npartner[i]; k++)
    if (p[k] == t) return values + ((bigint) i * capacity + k) * dnum;
  return nullptr;
}

void FixTaborHistory::store(int i, tagint t, const double *h)
{
  tagint *p = partner + (bigint) i * capacity;
  double *v = values + (bigint) i * capacity * dnum;
  for (int k = 0; k < npartner[i]; k++) {
    if (p[k] == t) {
      if (h[0] != 0.0) {
        if (v + k * dnum != h) memcpy(v + k * dnum, h, sizeof(double) * dnum);
      } else {
        int last = --npartner[i];
        p[k] = p[last];
        memmove(v + k * dnum, v + last * dnum, sizeof(double) * dnum);
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
  memcpy(v + npartner[i] * dnum, h, sizeof(double) * dnum);
  npartner[i]++;
}

/* A record refused by unpack_restart (on the rank that owns the atom) becomes
   one error->all on every rank, with the message of the lowest such rank. */
void FixTaborHistory::check_restart()
{
  int me = comm->me, first = 0;
  int mine = bad_record.empty() ? comm->nprocs : me;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, world);
  if (first == comm->nprocs) return;
  int length = me == first ? (int) bad_record.size() : 0;
  MPI_Bcast(&length, 1, MPI_INT, first, world);
  std::string message(length, ' ');
  if (me == first) message = bad_record;
  MPI_Bcast(&message[0], length, MPI_CHAR, first, world);
  error->all(FLERR, message);
}
