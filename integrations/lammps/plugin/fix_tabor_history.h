/* fix tabor/history: per-contact history of pair style tabor, stored with the
   atoms (partner tags and `width` doubles per partner) so that it moves with an
   atom between MPI ranks (pack/unpack_exchange), as LAMMPS's own
   fix neigh/history does, and is written to restart files (pack/unpack_restart):
   after read_restart, when pair style tabor recreates this fix (same ID), every
   contact gets its history back. Created by pair style tabor; not for direct use.

   Storage: per atom a row of `capacity` partners, grown (doubled, for all atoms)
   when an atom gets more contacts than fit, so there is no fixed limit. Memory:
   nmax * (12 + capacity * (16 + 8 * width)) bytes.

   Lifecycle: each atom has a creation stamp (new atoms get one above every
   stamp used before), each record its partner's stamp; an atom ID with another
   stamp is another atom, so a recycled ID starts clean, and the records of
   partners absent from a rebuilt neighbor list (deleted atoms) are dropped. */
#ifndef TABOR_FIX_HISTORY_H
#define TABOR_FIX_HISTORY_H

#include "fix.h"

#include <string>

namespace LAMMPS_NS {

class FixTaborHistory : public Fix {
 public:
  FixTaborHistory(class LAMMPS *, int, char **);
  ~FixTaborHistory() override;
  int setmask() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  // the doubles of one contact
  int width() const { return dnum; }
  // changes the doubles per contact, keeping the leading min(old, new) values of
  // every stored contact (the rest start at zero)
  void set_width(int);
  // the history of atom i with partner tag t of creation stamp st, or nullptr;
  // a record for tag t of another stamp (a deleted atom whose ID came back) is
  // removed
  double *find(int i, tagint t, double st);
  // stores h (width doubles) for (i, t, st); removes the entry when h[0] == 0
  // (h[0] is the contact flag)
  void store(int i, tagint t, double st, const double *h);
  // the creation stamp of atom i (local or ghost): an atom ID and its stamp
  // name one atom for the whole run, IDs recycled or not
  double stamp_of(int i) const { return stamp[i]; }
  // on every rank at setup: the next stamps above all held or issued
  void refresh_stamps();
  // drops the records whose partner is absent from a just-built neighbor list
  void drop_orphans(int inum, const int *ilist, const int *numneigh, int *const *firstneigh);
  // number of stored contacts of atom i
  int count(int i) const { return npartner[i]; }
  // one error->all on every rank if unpack_restart refused a record (call it on
  // every rank once the fix is made: the check is collective)
  void check_restart();

 private:
  int dnum;        // doubles per contact
  int capacity;    // partners per atom row
  int nmax_alloc;
  int *npartner;
  tagint *partner;    // nmax_alloc * capacity
  double *values;     // nmax_alloc * capacity * dnum
  double *stamp;     // per atom (ghosts too): creation stamp
  double *pstamp;    // nmax_alloc * capacity: the partner's stamp per record
  double next_stamp = 1.0;    // the base of the stamps set_arrays issues
  double issued_max = 0.0;    // the largest stamp this rank issued
  bigint issued = 0;          // stamps issued since refresh_stamps
  void remove(int i, int k);
  std::string bad_record;    // the first restart record refused on this rank
  void grow_capacity();
};

}    // namespace LAMMPS_NS

#endif
