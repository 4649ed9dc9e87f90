# UseBullet.cmake: what `include(${BULLET_USE_FILE})` does after find_package(Bullet CONFIG), as with
# upstream's install: Bullet's definitions, include and library directories for the whole directory.
# Prefer target_link_libraries(<target> ${BULLET_LIBRARIES}) (imported targets that carry all three).
add_definitions(${BULLET_DEFINITIONS})
include_directories(${BULLET_INCLUDE_DIRS})
link_directories(${BULLET_LIBRARY_DIRS})
