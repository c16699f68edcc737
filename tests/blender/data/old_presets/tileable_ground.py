import bpy
op = bpy.context.active_operator

op.method = 'ADDITIONS'
op.levels = 8
op.hurst = 0.6
op.sigma = 0.5
op.seed = 1
op.world_size = 10.0
op.periodic = True
op.use_sea_level = False
op.reference_source = 'NONE'
