/* fix wall/tabor and fix wall/tabor/region: tabor's contact laws (the models and
   keywords of pair_coeff of pair_style tabor, parsed by tabor_parse_coeff) between
   each particle of the group and a wall, with fix wall/gran's conventions:

     fix ID group wall/tabor MODEL ARGS [KEYWORDS] wallstyle args [keyword value ...]
       wallstyle: xplane|yplane|zplane lo hi (NULL: no wall there) | zcylinder radius
       keywords: wiggle dim amplitude period | shear dim vshear | contacts
     fix ID group wall/tabor/region MODEL ARGS [KEYWORDS] regionID [contacts]

   The wall is a flat half-space: R* = the particle's radius (the contact step is
   called with radius_j = +inf), E* the effective modulus of particle and wall,
   m* the particle's mass, torque arm R_i (fix wall/gran's). Every wall contact
   keeps the history of tabor_contact_step its model uses (tabor_contact_history_len:
   the normal turning point, the tangential, rolling and twisting displacements,
   10 doubles; with tangential mindlin_deresiewicz also the micro-slip spring bed,
   TABOR_CONTACT_HISTORY_LEN = 79 doubles, stepped where it lies): per atom up to `nslot`
   contacts (1 for a plane pair or a cylinder, the region's maximum number of
   surfaces touched at once for a region), each tagged with the wall it touches,
   carried with the atom between MPI ranks and written to restart files. */
#ifndef TABOR_FIX_WALL_TABOR_H
#define TABOR_FIX_WALL_TABOR_H

#include "fix.h"
#include "tabor_ffi.h"

#include <string>

namespace LAMMPS_NS {

class FixWallTabor : public Fix {
 public:
  FixWallTabor(class LAMMPS *, int, char **);
  ~FixWallTabor() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;

  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;
  void reset_dt() override;

 private:
  enum WallStyle { XPLANE = 0, YPLANE = 1, ZPLANE = 2, ZCYLINDER, REGION };
  std::string who;    // "fix wall/tabor" or "fix wall/tabor/region"
  TaborContact *contact;
  double rmax_seen;     // the largest particle radius met on this rank
  double reach_max;     // the largest interaction range of every radius met (tabor_contact_prepare)
  int wallstyle;
  double lo, hi, cylradius;
  int wiggle, wshear, axis;
  double amplitude, period, omega_wiggle, vshear;
  bigint time_origin;
  std::string idregion;
  tagint centre_on_wall;     // the lowest atom ID whose centre lies on a wall (setup)
  void all_contacts();
  std::string bad_record;    // the first restart record refused on this rank (raised in init)
  void check_restart();
  class Region *region;

  // per-atom contacts: ncontact[i] of nslot slots, each the wall's id and the
  // contact's hlen doubles (the leading part of a TaborContactHistory)
  int nslot;
  int hlen;    // tabor_contact_history_len: 10, or 79 with mindlin_deresiewicz
  int *ncontact;
  int *walls;          // nmax * nslot
  double *history;     // nmax * nslot * hlen
  int nmax_alloc;
  // a narrower history is stepped in this copy, whose micro-slip part stays zero
  // (a model without mindlin_deresiewicz never writes it)
  TaborContactHistory scratch;

  double *history_of(int i, int k) { return history + ((bigint) i * nslot + k) * hlen; }
  double *find_or_add(int i, int wall);
  void forget(int i, int wall);
  void grow_reach(double r);
  void one_contact(int i, int wall, const double *del, const double *vwall, double **contacts_out);
};

}    // namespace LAMMPS_NS

#endif
