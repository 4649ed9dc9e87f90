# The upstream demo side the project's ExampleBrowser app needs, built from the patched tree:
# glad, OpenGLWindow (X11 window loaded at run time, plus the OSMesa window of patch 0010), Gwen
# and the browser library; they link Bullet3Common and BulletSoftBody (the browser's OpenGLGuiHelper
# draws soft bodies) from cmake/BulletLibraries.cmake. Only the app and the render tests link these.

find_path(OSMESA_INCLUDE_DIR GL/osmesa.h)
find_library(OSMESA_LIBRARY OSMesa)
if(NOT OSMESA_INCLUDE_DIR OR NOT OSMESA_LIBRARY)
	message(FATAL_ERROR "OSMesa not found (GL/osmesa.h, libOSMesa): apt-get install libosmesa6-dev libgl-dev mesa-common-dev, "
		"or configure with -DBP_BUILD_BROWSER=OFF to build without the ExampleBrowser app")
endif()

set(BP_EXAMPLES "${BULLET_TREE}/examples")
set(BP_GL_DEFINITIONS GLEW_STATIC GLEW_INIT_OPENGL11_FUNCTIONS=1 GLEW_DYNAMIC_LOAD_ALL_GLX_FUNCTIONS=1
	DYNAMIC_LOAD_X11_FUNCTIONS=1 BT_USE_OSMESA)

# Upstream code, compiled as upstream ships it; its warnings are not ours to fix here.
function(bp_upstream_demo_target name)
	target_compile_options(${name} PRIVATE -w)
	target_compile_definitions(${name} PUBLIC ${BP_GL_DEFINITIONS})
	target_include_directories(${name} SYSTEM PUBLIC "${BULLET_TREE}/src" "${BP_EXAMPLES}" "${BP_EXAMPLES}/ThirdPartyLibs"
		"${BP_EXAMPLES}/ThirdPartyLibs/glad" "${BP_EXAMPLES}/ThirdPartyLibs/optionalX11")
	if(BP_UNITY_BUILD)
		set_target_properties(${name} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
	endif()
endfunction()

file(GLOB opengl_window_sources "${BP_EXAMPLES}/OpenGLWindow/*.cpp")
list(FILTER opengl_window_sources EXCLUDE REGEX "/(Mac|Win32|GLFW|EGL)[^/]*\\.cpp$")
add_library(OpenGLWindow STATIC ${opengl_window_sources}
	"${BP_EXAMPLES}/ThirdPartyLibs/glad/gl.c"
	"${BP_EXAMPLES}/ThirdPartyLibs/glad/glx.c"
	"${BP_EXAMPLES}/ThirdPartyLibs/stb_image/stb_image_write.cpp")
bp_upstream_demo_target(OpenGLWindow)
# osmesa.h is only included by OSMesaGLContext.cpp (patch 0010)
target_include_directories(OpenGLWindow PRIVATE "${OSMESA_INCLUDE_DIR}")
target_link_libraries(OpenGLWindow PUBLIC Bullet3Common ${OSMESA_LIBRARY} ${CMAKE_DL_LIBS})
# glad's gl.c and glx.c, fontstash and the font tables share file-local names: no unity build
set_target_properties(OpenGLWindow PROPERTIES UNITY_BUILD OFF)

file(GLOB gwen_sources "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/*.cpp" "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Controls/*.cpp"
	"${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Controls/Dialog/*.cpp" "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Controls/Dialogs/*.cpp"
	"${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Controls/Layout/*.cpp" "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Controls/Property/*.cpp"
	"${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Input/*.cpp" "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Platforms/*.cpp"
	"${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Renderers/*.cpp" "${BP_EXAMPLES}/ThirdPartyLibs/Gwen/Skins/*.cpp")
add_library(gwen STATIC ${gwen_sources})
bp_upstream_demo_target(gwen)
target_compile_definitions(gwen PUBLIC GWEN_COMPILE_STATIC _HAS_EXCEPTIONS=0)

file(GLOB gwen_gui_support_sources "${BP_EXAMPLES}/ExampleBrowser/GwenGUISupport/*.cpp")
add_library(BulletExampleBrowserLib STATIC
	"${BP_EXAMPLES}/ExampleBrowser/OpenGLExampleBrowser.cpp"
	"${BP_EXAMPLES}/ExampleBrowser/OpenGLGuiHelper.cpp"
	"${BP_EXAMPLES}/ExampleBrowser/GL_ShapeDrawer.cpp"
	"${BP_EXAMPLES}/ExampleBrowser/CollisionShape2TriangleMesh.cpp"
	"${BP_EXAMPLES}/Utils/b3Clock.cpp"
	"${BP_EXAMPLES}/Utils/ChromeTraceUtil.cpp"
	"${BP_EXAMPLES}/Utils/b3ResourcePath.cpp"
	${gwen_gui_support_sources})
bp_upstream_demo_target(BulletExampleBrowserLib)
target_include_directories(BulletExampleBrowserLib SYSTEM PUBLIC "${BP_EXAMPLES}/ExampleBrowser")
find_package(Threads REQUIRED)
target_link_libraries(BulletExampleBrowserLib PUBLIC OpenGLWindow gwen BulletSoftBody BulletDynamics Bullet3Common Threads::Threads)
