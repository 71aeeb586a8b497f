# Cross-compiling fxlab for 64-bit Windows with Debian's mingw-w64 (g++-mingw-w64-x86-64-posix: GCC
# with POSIX threads, so std::thread and std::mutex work). libgcc, libstdc++ and winpthread are linked
# statically: an .exe imports only Windows' own DLLs (KERNEL32, USER32, GDI32, SHELL32, msvcrt, ...)
# and a student installs nothing. The tests run the .exe's under Wine (CMAKE_CROSSCOMPILING_EMULATOR,
# set by tools/windows/build.sh to tools/windows/wine_run.sh).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(FX_MINGW_TRIPLE x86_64-w64-mingw32)

set(CMAKE_C_COMPILER ${FX_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${FX_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${FX_MINGW_TRIPLE}-windres)
set(CMAKE_AR ${FX_MINGW_TRIPLE}-gcc-ar-posix CACHE FILEPATH "")
set(CMAKE_RANLIB ${FX_MINGW_TRIPLE}-gcc-ranlib-posix CACHE FILEPATH "")

# Only the cross sysroot for libraries and headers; programs (glad, python3) from the host.
set(CMAKE_FIND_ROOT_PATH /usr/${FX_MINGW_TRIPLE})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# -static links winpthread (the POSIX thread model's runtime) into the .exe as well.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++")
