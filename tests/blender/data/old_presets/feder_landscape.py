import bpy
op = bpy.context.active_operator

op.method = 'ADDITIONS'
op.levels = 9
op.hurst = 0.7
op.sigma = 1.5
op.seed = 13
op.world_size = 20.0
op.periodic = False
op.use_sea_level = False
op.reference_source = 'NONE'
