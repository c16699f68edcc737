"""The Erode box of a terrain's settings (redo panel and sidebar), and the
preset menu whose choice fills the passes (build/erosion.py runs them)."""

from bpy.props import EnumProperty

from ...core import erosion, params
from ..common.widgets import draw_setting, draw_wrapped

# What the panels show of each process: its pass count, then its main rates.
_GROUPS = (
    ("Rivers", "fluvial_steps", ("erodibility", "uplift", "uplift_follows_terrain", "diffusion", "area_exponent",
                                "fluvial_dt")),
    ("Rain", "hydraulic_iterations", ("rain", "evaporation", "capacity", "dissolve", "deposit")),
    ("Scree", "thermal_iterations", ("talus_degrees", "thermal_rate")),
)


def apply_preset(data):
    """Shows the chosen preset's passes in `data` (operator or PropertyGroup),
    so that switching to Custom starts from them; None zeroes the passes,
    Custom leaves everything."""
    preset = data.erode_preset
    if preset == "CUSTOM":
        return
    if preset == "NONE":
        for name in erosion.COUNTS:
            setattr(data, name, 0)
        if hasattr(data, "duration"):
            data.duration = 0.0
        return
    values = erosion.preset_values(preset.lower())
    for name in erosion.PRESET_FIELDS:
        if hasattr(data, name):
            setattr(data, name, values[name])


def preset_property(then=None, options=None):
    """The erode_preset EnumProperty whose update applies the preset (then calls `then`)."""
    p = params.PARAMS_BY_NAME["erode_preset"]

    def update(self, context):
        apply_preset(self)
        if then is not None:
            then(self, context)

    return EnumProperty(name=p.label, description=p.description, default=p.default,
                        items=[(ident, label, tip, number) for ident, label, tip, number in p.items],
                        update=update, **({"options": options} if options is not None else {}))


def draw_erosion(layout, data):
    """The Erode box of the settings: the preset, then each process's passes
    (editable with Custom; a preset shows its own) and rates."""
    box = layout.box().column(align=True)
    # A heading, then the menu across the box: as one split row the narrow
    # sidebar cut its label to "Erosi..." (issue 17).
    box.label(text=params.PARAMS_BY_NAME["erode_preset"].label)
    box.prop(data, "erode_preset", text="")
    if data.erode_preset == "NONE":
        return
    for title, count, rates in _GROUPS:
        sub = box.column(align=True)
        # The process as a heading, its count as a whole row: "Scree: Scree Passes"
        # in one field was cut to "Scree Pas..." in the sidebar.
        sub.label(text=title)
        row = sub.row(align=True)
        row.enabled = data.erode_preset == "CUSTOM"
        row.prop(data, count)
        if getattr(data, count) > 0:
            for name in rates:
                if name in erosion.FITTED and data.erode_preset != "CUSTOM":
                    # A preset fits them to the terrain (the library's ft_terrain_build).
                    if name == "uplift":
                        draw_wrapped(sub, f"{params.PARAMS_BY_NAME[name].label}: fitted to the terrain", width=30)
                    continue
                draw_setting(sub, data, name, params.PARAMS_BY_NAME[name])
