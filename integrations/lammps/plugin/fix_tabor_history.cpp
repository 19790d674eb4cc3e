#include "fix_tabor_history.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixTaborHistory::FixTaborHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), overflow(0), npartner(nullptr), partner(nullptr), hist(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal fix tabor/history command");
  create_attribute = 1;
  maxexchange = 1 + MAXPARTNER * (1 + TABOR_HISTORY_LEN);
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  for (int i = 0; i < atom->nmax; i++) npartner[i] = 0;
}

FixTaborHistory::~FixTaborHistory()
{
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(npartner);
  memory->destroy(partner);
  memory->sfree(hist);
}

int FixTaborHistory::setmask()
{
  return 0;
}

void FixTaborHistory::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "tabor/history:npartner");
  memory->grow(partner, nmax, MAXPARTNER, "tabor/history:partner");
  // one contiguous block of nmax * MAXPARTNER histories
  TaborHistory *old = hist ? hist[0] : nullptr;
  auto *block = (TaborHistory *) memory->srealloc(old, sizeof(TaborHistory) * nmax * MAXPARTNER,
                                                  "tabor/history:block");
  hist = (TaborHistory **) memory->srealloc(hist ? hist : nullptr, sizeof(TaborHistory *) * nmax,
                                            "tabor/history:hist");
  for (int i = 0; i < nmax; i++) hist[i] = block + (bigint) i * MAXPARTNER;
}

void FixTaborHistory::copy_arrays(int i, int j, int /*delflag*/)
{
  npartner[j] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    partner[j][k] = partner[i][k];
    hist[j][k] = hist[i][k];
  }
}

void FixTaborHistory::set_arrays(int i)
{
  npartner[i] = 0;
}

int FixTaborHistory::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) {
    buf[m++] = ubuf(partner[i][k]).d;
    buf[m++] = hist[i][k].contact;
    buf[m++] = hist[i][k].max_overlap;
  }
  return m;
}

int FixTaborHistory::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  npartner[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < npartner[nlocal]; k++) {
    partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
    hist[nlocal][k].contact = buf[m++];
    hist[nlocal][k].max_overlap = buf[m++];
  }
  return m;
}

double FixTaborHistory::memory_usage()
{
  return (double) atom->nmax * (sizeof(int) + MAXPARTNER * (sizeof(tagint) + sizeof(TaborHistory)));
}

TaborHistory *FixTaborHistory::find(int i, tagint t)
{
  for (int k = 0; k < npartner[i]; k++)
    if (partner[i][k] == t) return &hist[i][k];
  return nullptr;
}

void FixTaborHistory::store(int i, tagint t, const TaborHistory &h)
{
  for (int k = 0; k < npartner[i]; k++) {
    if (partner[i][k] == t) {
      if (h.contact != 0.0) {
        hist[i][k] = h;
      } else {
        int last = --npartner[i];
        partner[i][k] = partner[i][last];
        hist[i][k] = hist[i][last];
      }
      return;
    }
  }
  if (h.contact == 0.0) return;
  if (npartner[i] >= MAXPARTNER) {
    overflow++;
    return;
  }
  partner[i][npartner[i]] = t;
  hist[i][npartner[i]] = h;
  npartner[i]++;
}
