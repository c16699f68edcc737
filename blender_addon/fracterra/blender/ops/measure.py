# SPDX-License-Identifier: GPL-3.0-or-later
"""Object > Measure: H and D of a terrain, eta, chi, gamma and box-counting D of
a curve, stored in the object's FRACTERRA_PG_measures for the sidebar."""

import math

import bpy
from mathutils import Matrix

from ... import core
from ..build.curve import curve_polylines
from ..common.reporting import REPORTED, SettingsError
from ..build.objects import active_object, geometry_fingerprint, heightfield_of, is_measurable


class FRACTERRA_OT_measure(bpy.types.Operator):
    """Measure the active terrain (H, D) or curve (eta, chi, gamma, box-counting D)"""
    bl_idname = "object.fracterra_measure"
    bl_label = "Measure"
    bl_options = {"REGISTER"}

    @classmethod
    def poll(cls, context):
        return is_measurable(active_object(context))

    def execute(self, context):
        obj = active_object(context)
        m = obj.fracterra_measures
        try:
            if obj.type == "CURVE":
                pl = curve_polylines(obj, Matrix.Identity(4))
                if pl is None:
                    raise SettingsError(f"the curve '{obj.name}' has no spline with 2 or more points")
                with pl:
                    s = pl.measure()
                m.kind, m.eta, m.chi, m.gamma = "polylines", s["eta"], s["chi"], s["gamma"]
                m.dimension, m.stderr, m.hurst = s["box_dimension"], s["box_dimension_std_error"], math.nan
            else:
                with heightfield_of(obj) as hf:
                    r = core.hurst_of_heightfield(hf)  # the library's recommended estimator, as the CLI's
                m.kind, m.hurst, m.dimension, m.stderr = "terrain", r["hurst"], r["dimension"], r["std_error"]
                m.estimator, m.estimator_reason = r["estimator"], r["reason"]
                m.eta = m.chi = m.gamma = math.nan
        except REPORTED as e:
            self.report({"ERROR"}, str(e))
            return {"CANCELLED"}
        m.geometry = geometry_fingerprint(obj)
        return {"FINISHED"}
