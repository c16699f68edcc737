import bpy
op = bpy.context.active_operator

op.levelling = 1.0
op.height_offset = 0.0
op.falloff = 'NONE'
op.falloff_width = 0.3
op.edge_level = 0.0
op.sea = 'FRACTION'
op.sea_level = 0.0
op.sea_fraction = 0.35
op.periodic = False
op.uvs = True
op.smooth = True
op.reference_source = 'NONE'
op.method = 'ADDITIONS'
op.levels = 9
op.hurst = 0.7
op.sigma = 1.5
op.seed = 13
op.world_size = 20.0
