//VTK::System::Dec
// Ambient Occlusion Volumes (McGuire 2010), stage 1 of 3: the occluding triangles, shifted
// to a scene origin on the CPU for precision, go to view space; the geometry shader builds
// each triangle's volume there.
in vec4 vertexMC;          // xyz: position relative to the scene origin; w: 1 = two-sided
uniform mat4 aoModelView;  // world (shifted) -> view
out vec3 aoVertexVC;
out float aoTwoSidedVS;

void main()
{
  aoVertexVC = (aoModelView * vec4(vertexMC.xyz, 1.0)).xyz;
  aoTwoSidedVS = vertexMC.w;
  gl_Position = vec4(aoVertexVC, 1.0);
}
