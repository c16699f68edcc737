import bpy
op = bpy.context.active_operator

op.method = 'MIDPOINT'
op.levels = 9
op.hurst = 0.75
op.sigma = 2.0
op.seed = 3
op.world_size = 40.0
op.periodic = False
op.use_sea_level = True
op.sea_level = 0.5
op.reference_source = 'NONE'
