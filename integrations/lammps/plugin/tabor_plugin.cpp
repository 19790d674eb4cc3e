/* Registers pair_style tabor and its history fix with LAMMPS (plugin load). */
#include "tabor_lammpsplugin.h"

#include "fix_tabor_history.h"
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
}
