import bpy
op = bpy.context.active_operator

op.levelling = 1.0
op.height_offset = 0.0
op.falloff = 'SQUARE'
op.falloff_width = 0.15
op.edge_level = -1.0
op.sea = 'NONE'
op.sea_level = 0.0
op.sea_fraction = 0.3
op.periodic = False
op.uvs = True
op.smooth = True
op.reference_source = 'NONE'
op.method = 'MIDPOINT'
op.levels = 9
op.hurst = 0.4
op.sigma = 0.6
op.seed = 5
op.world_size = 20.0
