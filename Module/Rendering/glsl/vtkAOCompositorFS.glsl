//VTK::System::Dec
// Composite: modulate the shaded image by A^Intensity, or show A itself (AO-only), and write
// the G-buffer depth so later passes (translucent props, overlays) are depth-tested correctly.
in vec2 texCoord;
uniform sampler2D aoColor;
uniform sampler2D aoDepth;
uniform sampler2D aoOcclusion;  // r = A
uniform ivec2 aoFullSize;
uniform int aoOcclusionScale;   // 1 for the filtered map, the AO scale for the raw one
uniform int aoOnly;
uniform int aoKeepBackground;   // 1: leave background pixels to what lies below (layers)
uniform float aoIntensity;
//VTK::Output::Dec

void main()
{
  ivec2 pix = min(ivec2(texCoord * vec2(aoFullSize)), aoFullSize - 1);
  float depth = texelFetch(aoDepth, pix, 0).r;
  vec4 color = texelFetch(aoColor, pix, 0);
  if (depth >= 1.0)
  {
    if (aoKeepBackground != 0)
    {
      discard;
    }
    gl_FragData[0] = aoOnly != 0 ? vec4(1.0) : color;
    gl_FragDepth = depth;
    return;
  }
  ivec2 aoSize = textureSize(aoOcclusion, 0);
  float a = clamp(texelFetch(aoOcclusion, min(pix / aoOcclusionScale, aoSize - 1), 0).r, 0.0, 1.0);
  gl_FragData[0] = aoOnly != 0 ? vec4(a, a, a, 1.0) : vec4(color.rgb * pow(a, aoIntensity), color.a);
  gl_FragDepth = depth;
}
