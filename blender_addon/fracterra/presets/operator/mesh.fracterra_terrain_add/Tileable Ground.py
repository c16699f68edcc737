import bpy
op = bpy.context.active_operator

op.levelling = 0.0
op.height_offset = 0.0
op.falloff = 'NONE'
op.falloff_width = 0.3
op.edge_level = 0.0
op.sea = 'NONE'
op.sea_level = 0.0
op.sea_fraction = 0.3
op.periodic = True
op.uvs = True
op.smooth = True
op.reference_source = 'NONE'
op.method = 'ADDITIONS'
op.levels = 8
op.hurst = 0.6
op.sigma = 0.15
op.seed = 1
op.world_size = 10.0
