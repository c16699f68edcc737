# SPDX-License-Identifier: GPL-3.0-or-later
"""What every Regenerate operator shares (terrains, planets): it rebuilds the
target of the active object as a cancellable job, and after a cancel or a
failure the sidebar shows the settings of the mesh that is there."""

import bpy

from ..common.jobs import JobOperator
from ..build.objects import active_object, editable_settings, restore_settings


class RegenerateOperator(JobOperator):
    """Mixin before bpy.types.Operator: subclasses give target_of(obj) (the
    object whose settings the sidebar shows for the active object, or None),
    regenerate_job(obj, context) and noun (what the reports call it)."""

    noun = "object"

    @staticmethod
    def target_of(obj):
        raise NotImplementedError

    @staticmethod
    def regenerate_job(obj, context):
        raise NotImplementedError

    @classmethod
    def poll(cls, context):
        return context.mode == "OBJECT" and cls.target_of(active_object(context)) is not None

    def make_job(self, context):
        obj = self.target_of(active_object(context))
        editable_settings(obj)[0].last_error = ""
        self._target_name = obj.name
        return self.regenerate_job(obj, context)

    def _target(self):
        obj = bpy.data.objects.get(getattr(self, "_target_name", ""))
        return obj if obj is not None else self.target_of(active_object(bpy.context))

    def job_cancelled(self, context):
        # The mesh is the one from before: so are the settings shown.
        restore_settings(self._target())

    def _refuse(self, e):
        obj = self._target()
        editable = editable_settings(obj)
        if editable is not None:
            restore_settings(obj)
            editable[0].last_error = str(e)
        return super()._refuse(e)

    def job_done(self, context, summary):
        self.report({"INFO"}, f"Fractal {self.noun}: {summary} in {self.job_seconds:.2f} s")
        return {"FINISHED"}
