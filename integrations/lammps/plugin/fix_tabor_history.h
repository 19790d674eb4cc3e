/* fix tabor/history: per-contact history of pair style tabor, stored with the
   atoms (partner tags and TABOR_HISTORY_LEN doubles per partner) so that it moves
   with an atom between MPI ranks (pack/unpack_exchange), as LAMMPS's own
   fix neigh/history does. Created by pair style tabor; not for direct use. */
#ifndef TABOR_FIX_HISTORY_H
#define TABOR_FIX_HISTORY_H

#include "fix.h"
#include "tabor_ffi.h"

namespace LAMMPS_NS {

class FixTaborHistory : public Fix {
 public:
  static constexpr int MAXPARTNER = 24;

  FixTaborHistory(class LAMMPS *, int, char **);
  ~FixTaborHistory() override;
  int setmask() override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  double memory_usage() override;

  // the history of atom i with partner tag t, or nullptr
  TaborHistory *find(int i, tagint t);
  // stores h for (i, t); removes the entry when h.contact == 0
  void store(int i, tagint t, const TaborHistory &h);
  int overflow;    // entries that did not fit (reported by the pair style)

 private:
  int *npartner;
  tagint **partner;
  TaborHistory **hist;
};

}    // namespace LAMMPS_NS

#endif
