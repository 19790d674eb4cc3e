"""ctypes binding of tabor-ffi (libtabor_ffi.so): law info (jump-in, snap-off,
interaction range, pull-off force) for the plugin tests."""

import ctypes
import os

MODELS = {"hertz": 0, "jkr/fixed-grip": 1, "jkr/load-controlled": 2, "maugis": 3}


class Params(ctypes.Structure):
    _fields_ = [("model", ctypes.c_int32), ("effective_modulus", ctypes.c_double),
                ("effective_radius", ctypes.c_double), ("work_of_adhesion", ctypes.c_double),
                ("tabor_parameter", ctypes.c_double), ("damping_time", ctypes.c_double),
                ("damping_model", ctypes.c_int32), ("damping_value", ctypes.c_double),
                ("dugdale_range", ctypes.c_double), ("cohesive_stress", ctypes.c_double)]


class Info(ctypes.Structure):
    _fields_ = [(n, ctypes.c_double) for n in (
        "jump_in_overlap", "snap_off_overlap", "interaction_range", "pull_off_force",
        "force_scale", "table_force_error", "table_force_relative_error")]


def law_info(lib_path, model, e_star, r_star, w=0.0, lam=0.0, damping=0.0):
    lib = ctypes.CDLL(lib_path)
    p = Params(MODELS[model], e_star, r_star, w, lam, damping)
    law = ctypes.c_void_p()
    st = lib.tabor_law_new(ctypes.byref(p), ctypes.byref(law))
    if st != 0:
        buf = ctypes.create_string_buffer(512)
        lib.tabor_last_error(buf, 512)
        raise RuntimeError(f"tabor_law_new: {st} {buf.value.decode()}")
    info = Info()
    assert lib.tabor_law_info(law, ctypes.byref(info)) == 0
    lib.tabor_law_free(law)
    return info
