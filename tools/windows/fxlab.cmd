@echo off
rem fxlab.cmd: the commands of the Linux ./fxlab script, on Windows (README.txt says how to use them).
rem   fxlab list | fxlab run 01 [options] | fxlab exercise list | fxlab exercise start 04 1
rem   fxlab check 04 1 | fxlab check --all | fxlab handout 06 [--lang ja]
setlocal EnableExtensions
set "HERE=%~dp0"
set "COMMAND=%~1"
if "%COMMAND%"=="" goto usage
shift
if /i "%COMMAND%"=="list" goto list
if /i "%COMMAND%"=="run" goto run
if /i "%COMMAND%"=="exercise" goto exercise
if /i "%COMMAND%"=="check" goto check
if /i "%COMMAND%"=="handout" goto handout
echo fxlab: unknown command "%COMMAND%" 1>&2
goto usage

:list
for %%f in ("%HERE%fxlab-[0-9][0-9]-*.exe") do echo   %%~nf
exit /b 0

:run
call :find "%~1" || exit /b 2
shift
call :rest %1 %2 %3 %4 %5 %6 %7 %8 %9
"%LESSON%" %REST%
exit /b %ERRORLEVEL%

:exercise
if /i "%~1"=="list" ( "%HERE%fxlab-exercise.exe" list & exit /b %ERRORLEVEL% )
if /i not "%~1"=="start" goto usage
if "%~3"=="" goto usage
"%HERE%fxlab-exercise.exe" start %2 %3 >nul || exit /b 1
call :find "%~2" || exit /b 2
set /a NUMBER=1%~3 %% 100
"%LESSON%" --exercise %NUMBER%
exit /b %ERRORLEVEL%

:check
call :rest %1 %2 %3 %4 %5 %6 %7 %8 %9
"%HERE%fxlab-exercise.exe" check %REST%
exit /b %ERRORLEVEL%

:handout
set "LESSONS="
set "OPTIONS="
:handout_next
if "%~1"=="" goto handout_run
set "ARG=%~1"
if "%ARG:~0,1%"=="-" (
  set OPTIONS=%OPTIONS% %1
  if /i "%ARG%"=="--lang" ( set OPTIONS=%OPTIONS% %2 & shift )
  if /i "%ARG%"=="--out" ( set OPTIONS=%OPTIONS% %2 & shift )
) else (
  call :find "%ARG%" || exit /b 2
  call set LESSONS=%%LESSONS%% "%%LESSON%%"
)
shift
goto handout_next
:handout_run
"%HERE%fxlab-handout.exe" %OPTIONS% %LESSONS%
exit /b %ERRORLEVEL%

rem :find NUMBER-or-NAME sets LESSON to the lesson's .exe (01, 1, bloom, 06-bloom).
:find
set "WANT=%~1"
set "LESSON="
if "%WANT%"=="" goto find_failed
if "%WANT:~1%"=="" set "WANT=0%WANT%"
for %%f in ("%HERE%fxlab-%WANT%-*.exe") do set "LESSON=%%~ff"
if not defined LESSON for %%f in ("%HERE%fxlab-*-%WANT%.exe" "%HERE%fxlab-%WANT%.exe") do if exist "%%~ff" set "LESSON=%%~ff"
if defined LESSON exit /b 0
:find_failed
echo fxlab: no lesson "%~1"; these exist: 1>&2
for %%f in ("%HERE%fxlab-[0-9][0-9]-*.exe") do echo   %%~nf 1>&2
exit /b 1

rem :rest ARG... sets REST to the arguments given, quotes kept.
:rest
set "REST="
:rest_next
if "%~1"=="" exit /b 0
set REST=%REST% %1
shift
goto rest_next

:usage
echo usage: fxlab ^<command^> [args]
echo   list                       the lessons
echo   run ^<lesson^> [options]     open a lesson: fxlab run 01, fxlab run bloom --lang ja
echo   exercise list              the exercises and where you stand
echo   exercise start ^<LL^> ^<N^>    copy exercise N of lesson LL to %%USERPROFILE%%\fxlab-exercises and open it
echo   check ^<LL^> ^<N^>             grade your exercise (check --all: every one)
echo   handout ^<lesson^>... [--lang en^|ja]   a lesson as a page to keep (needs Graphviz's dot on PATH)
exit /b 2
