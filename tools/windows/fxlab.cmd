@echo off
rem fxlab.cmd: the commands of the Linux ./fxlab script, on Windows (README.txt says how to use them).
rem   fxlab list | fxlab run 01 [options] | fxlab exercise list | fxlab exercise start 04 1
rem   fxlab check 04 1 | fxlab check --all | fxlab handout 06 [--lang ja]
setlocal EnableExtensions
set "HERE=%~dp0"
rem The whole command line as typed: %1..%9 would split "--param name=value" at the "=".
set ALL=%*
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
for /f "delims=" %%f in ('dir /b "%HERE%fxlab-??-*.exe" 2^>nul') do echo   %%~nf
exit /b 0

:run
call :find "%~1"
if errorlevel 1 exit /b 2
call :after 2
"%LESSON%" %REST%
exit /b %ERRORLEVEL%

:exercise
if /i "%~1"=="list" ( "%HERE%fxlab-exercise.exe" list & exit /b %ERRORLEVEL% )
if /i not "%~1"=="start" goto usage
if "%~3"=="" goto usage
"%HERE%fxlab-exercise.exe" start %2 %3 >nul
if errorlevel 1 exit /b 1
call :find "%~2"
if errorlevel 1 exit /b 2
set /a NUMBER=1%~3 %% 100
"%LESSON%" --exercise %NUMBER%
exit /b %ERRORLEVEL%

:check
call :after 1
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
  call :find "%ARG%"
  if errorlevel 1 exit /b 2
  call set LESSONS=%%LESSONS%% "%%LESSON%%"
)
shift
goto handout_next
:handout_run
"%HERE%fxlab-handout.exe" %OPTIONS% %LESSONS%
exit /b %ERRORLEVEL%

rem (Its callers test errorlevel on the next line: Wine's cmd mistakes "call :find ... || ..." for a failure.)
rem :find NUMBER-or-NAME sets LESSON to the lesson's .exe (01, 1, bloom, 06-bloom).
:find
set "WANT=%~1"
set "LESSON="
if "%WANT%"=="" goto find_failed
if "%WANT:~1%"=="" set "WANT=0%WANT%"
rem dir /b, not a for over a quoted pattern: Wine's cmd matches no wildcard in a quoted absolute path.
for /f "delims=" %%f in ('dir /b "%HERE%fxlab-%WANT%-*.exe" 2^>nul') do set "LESSON=%HERE%%%f"
if defined LESSON exit /b 0
for /f "delims=" %%f in ('dir /b "%HERE%fxlab-??-%WANT%.exe" 2^>nul') do set "LESSON=%HERE%%%f"
if defined LESSON exit /b 0
if exist "%HERE%fxlab-%WANT%.exe" set "LESSON=%HERE%fxlab-%WANT%.exe"
if defined LESSON exit /b 0
:find_failed
echo fxlab: no lesson "%~1"; these exist: 1>&2
for /f "delims=" %%f in ('dir /b "%HERE%fxlab-??-*.exe" 2^>nul') do echo   %%~nf 1>&2
exit /b 1

rem :after N sets REST to the command line after its first N words, as typed (quotes and "=" kept).
:after
set "REST="
if "%~1"=="1" for /f "tokens=1,*" %%a in ("%ALL:"=""%") do set "REST=%%b"
if "%~1"=="2" for /f "tokens=1,2,*" %%a in ("%ALL:"=""%") do set "REST=%%c"
if defined REST set "REST=%REST:""="%"
exit /b 0

:usage
echo usage: fxlab ^<command^> [args]
echo   list                       the lessons
echo   run ^<lesson^> [options]     open a lesson: fxlab run 01, fxlab run bloom --lang ja
echo   exercise list              the exercises and where you stand
echo   exercise start ^<LL^> ^<N^>    copy exercise N of lesson LL to %%USERPROFILE%%\fxlab-exercises and open it
echo   check ^<LL^> ^<N^>             grade your exercise (check --all: every one)
echo   handout ^<lesson^>... [--lang en^|ja]   a lesson as a page to keep (needs Graphviz's dot on PATH)
exit /b 2
