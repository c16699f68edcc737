import bpy
op = bpy.context.active_operator

op.method = 'MIDPOINT'
op.levels = 9
op.hurst = 0.35
op.sigma = 1.0
op.seed = 5
op.world_size = 20.0
op.periodic = False
op.use_sea_level = False
op.reference_source = 'NONE'
