/* LD_PRELOAD shim for scripts/run-sanitizers.sh: dlclose() does nothing, so every library a
 * process loads stays mapped until it exits.
 *
 * Why: Mesa's GLX unloads its DRI driver (swrast_dri.so: llvmpipe) when VTK closes the X display,
 * before LeakSanitizer's check at exit. The driver's own allocations that are still alive then
 * point into code that is no longer mapped, so LeakSanitizer can neither name the module nor
 * match the `leak:swrast_dri.so` suppression, and reports them unsymbolized (the "112 bytes in
 * 2 calloc blocks" of Documentation/reliability.md, which valgrind, which keeps symbols of
 * unloaded code, shows inside Mesa below vtkOpenGLPolyDataMapper::RenderPieceDraw). With the
 * driver kept loaded the frames are named and suppressed like every other Mesa allocation.
 * The libraries' destructors run at exit instead of at dlclose.
 *
 * It is loaded before the AddressSanitizer runtime, hence ASAN_OPTIONS=verify_asan_link_order=0
 * in the script (it defines no function ASan intercepts except dlclose itself, whose interceptor
 * only refreshes ASan's module list).
 */
int dlclose(void* handle)
{
  (void)handle;
  return 0;
}
