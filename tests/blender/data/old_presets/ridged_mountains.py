import bpy
op = bpy.context.active_operator

op.method = 'FBM'
op.width = 513
op.height = 513
op.hurst = 0.9
op.sigma = 3.0
op.seed = 21
op.world_size = 40.0
op.basis = 'GRADIENT'
op.variant = 'RIDGED'
op.octaves = 10
op.frequency = 3.0
op.octave_rotation = 0.5
op.use_sea_level = False
op.reference_source = 'NONE'
