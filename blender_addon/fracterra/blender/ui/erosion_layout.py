"""The Erode box of a terrain's settings (redo panel and sidebar), and the
preset menu whose choice fills the passes (build/erosion.py runs them)."""

from bpy.props import EnumProperty

from ...core import erosion, params

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
    counts = erosion.preset_values(preset.lower()) if preset != "NONE" else {}
    for name in erosion.COUNTS:
        setattr(data, name, counts.get(name, 0))


def preset_property(then=None):
    """The erode_preset EnumProperty whose update applies the preset (then calls `then`)."""
    p = params.PARAMS_BY_NAME["erode_preset"]

    def update(self, context):
        apply_preset(self)
        if then is not None:
            then(self, context)

    return EnumProperty(name=p.label, description=p.description, default=p.default,
                        items=[(ident, label, tip, number) for ident, label, tip, number in p.items],
                        update=update)


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
        row = sub.row(align=True)
        row.enabled = data.erode_preset == "CUSTOM"
        row.prop(data, count, text=f"{title}: {params.PARAMS_BY_NAME[count].label}")
        if getattr(data, count) > 0:
            for name in rates:
                if name in erosion.FITTED and data.erode_preset != "CUSTOM":
                    # A preset fits them to the terrain (the library's ft_terrain_build).
                    if name == "uplift":
                        sub.label(text=f"{params.PARAMS_BY_NAME[name].label}: fitted to the terrain")
                    continue
                # A value too small for Blender's 6 decimals is drawn scaled (props.display_property).
                shown = params.shown_name(name) if params.PARAMS_BY_NAME[name].display_scale else name
                sub.prop(data, shown)
