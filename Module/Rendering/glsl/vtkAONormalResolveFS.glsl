//VTK::System::Dec
// Completes the G-buffer's normal attachment where the mapper wrote none (w = 0: shaders
// without a normal, such as unlit props, and mappers outside vtkPolyDataMapper's hooks): the
// polygon's normal rebuilt from the neighbouring depths (aoFacetNormal), with w = 1. Drawn with
// blending (1 - destination alpha, destination alpha) over the attachment, so that the normals
// the mappers wrote (w = 1) stay as they are; the background (depth 1) keeps w = 0. Run by
// vtkAOGBufferPass only for frames that drew such a prop, so that the AO stages never rebuild
// a normal themselves (aoViewNormal).
in vec2 texCoord;
uniform sampler2D aoDepth;
uniform sampler2D aoNormal; // unused here (aoViewNormal in AO::Common needs its name)
uniform mat4 aoInvProjection;
uniform ivec2 aoFullSize;
uniform int aoParallel;
//VTK::Output::Dec

//AO::Common

void main()
{
  ivec2 pix = min(ivec2(texCoord * vec2(aoFullSize)), aoFullSize - 1);
  float depth = texelFetch(aoDepth, pix, 0).r;
  if (depth >= 1.0)
  {
    gl_FragData[0] = vec4(0.0);
    return;
  }
  vec3 p = aoViewPosition(pix, depth);
  gl_FragData[0] = vec4(normalize(aoFacetNormal(pix, p)), 1.0);
}
