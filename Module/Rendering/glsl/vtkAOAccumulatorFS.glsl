//VTK::System::Dec
// Running mean of A (vtkAOAccumulator): the first frame is copied as is; later frames are
// blended into the mean by the fixed-function blend, their alpha carrying the weight 1/k
// (only the red channel, A, is written then). Scatter mode writes a map of one texel every
// aoScatterScale pixels, evaluated at the pixel aoScatterOffset of each block, at those
// pixels only (a stratified accumulation: vtkAmbientOcclusionPassBase).
in vec2 texCoord;
uniform sampler2D aoFrame;
uniform int aoCopy;           // 1: every channel (the first frame, or scatter)
uniform float aoWeight;       // 1 / k for the k-th frame
uniform int aoScatterScale;   // > 0: scatter mode, the map's block size
uniform ivec2 aoScatterOffset; // scatter mode: the pixel of each block the map holds
//VTK::Output::Dec

void main()
{
  if (aoScatterScale > 0)
  {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    if (any(notEqual(pix % aoScatterScale, aoScatterOffset)))
    {
      discard;
    }
    gl_FragData[0] = texelFetch(aoFrame, pix / aoScatterScale, 0);
    return;
  }
  // The mean has the frame's size: one texel per fragment.
  vec4 frame = texelFetch(aoFrame, ivec2(texCoord * vec2(textureSize(aoFrame, 0))), 0);
  gl_FragData[0] = aoCopy != 0 ? frame : vec4(frame.rgb, aoWeight);
}
