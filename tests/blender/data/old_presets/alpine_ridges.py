import bpy
op = bpy.context.active_operator

op.method = 'MIDPOINT'
op.levels = 9
op.hurst = 0.9
op.sigma = 3.0
op.seed = 11
op.world_size = 40.0
op.periodic = False
op.use_sea_level = False
op.uvs = True
op.smooth = True
op.reference_source = 'NONE'
