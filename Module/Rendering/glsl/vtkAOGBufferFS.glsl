  // Ambient-occlusion G-buffer: the view-space normal in attachment 1. Translucent props write
  // alpha 0, which blending turns into "keep what the opaque props wrote".
  //AO::GBuffer::Normal
