//VTK::System::Dec
// Running mean of A (vtkAOAccumulator): the first frame is copied as is; later frames are
// blended into the mean by the fixed-function blend, their alpha carrying the weight 1/k
// (only the red channel, A, is written then).
in vec2 texCoord;
uniform sampler2D aoFrame;
uniform int aoCopy;     // 1: first frame, every channel
uniform float aoWeight; // 1 / k for the k-th frame
//VTK::Output::Dec

void main()
{
  // The mean has the frame's size: one texel per fragment.
  vec4 frame = texelFetch(aoFrame, ivec2(texCoord * vec2(textureSize(aoFrame, 0))), 0);
  gl_FragData[0] = aoCopy != 0 ? frame : vec4(frame.rgb, aoWeight);
}
