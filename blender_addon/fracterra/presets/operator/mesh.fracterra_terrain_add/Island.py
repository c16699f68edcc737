import bpy
op = bpy.context.active_operator

op.levelling = 1.0
op.height_offset = 4.0
op.falloff = 'RADIAL'
op.falloff_width = 1.0
op.edge_level = -1.5
op.sea = 'HEIGHT'
op.sea_level = 0.0
op.sea_fraction = 0.3
op.periodic = False
op.uvs = True
op.smooth = True
op.reference_source = 'NONE'
op.method = 'MIDPOINT'
op.levels = 9
op.hurst = 0.8
op.sigma = 2.0
op.seed = 4
op.world_size = 30.0
