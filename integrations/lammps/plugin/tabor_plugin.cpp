/* Registers pair_style tabor, its history fix, fix wall/tabor and fix
   wall/tabor/region with LAMMPS (plugin load). */
#include "tabor_lammpsplugin.h"

#include "fix_tabor_history.h"
#include "fix_wall_tabor.h"
#include "lammps.h"
#include "pair_tabor.h"

using namespace LAMMPS_NS;

#ifndef TABOR_LAMMPS_VERSION
#error "TABOR_LAMMPS_VERSION (the LAMMPS version string the plugin is built for) must be defined"
#endif

static Pair *pair_tabor_creator(LAMMPS *lmp)
{
  return new PairTabor(lmp);
}

static Fix *fix_tabor_history_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixTaborHistory(lmp, argc, argv);
}

static Fix *fix_wall_tabor_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixWallTabor(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  plugin.version = TABOR_LAMMPS_VERSION;
  plugin.style = "pair";
  plugin.name = "tabor";
  plugin.info = "tabor contact laws: Hertz, JKR (fixed grip / load controlled), Maugis-Dugdale";
  plugin.author = "tabor developers";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_tabor_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "tabor/history";
  plugin.info = "per-contact history of pair style tabor (moves with the atoms)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_tabor_history_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "wall/tabor";
  plugin.info = "tabor contact laws between particles and a plane or cylinder wall (as fix wall/gran)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_wall_tabor_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "wall/tabor/region";
  plugin.info = "tabor contact laws between particles and a region's surface (as fix wall/gran/region)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_wall_tabor_creator;
  (*register_plugin)(&plugin, lmp);
}
