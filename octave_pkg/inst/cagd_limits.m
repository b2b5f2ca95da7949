## -*- texinfo -*-
## @deftypefn  {} {@var{L} =} cagd_limits ()
## @deftypefnx {} {@var{L} =} cagd_limits (@var{name}, @var{value})
## @deftypefnx {} {@var{L} =} cagd_limits ("default")
## The resource limits of the cagd package in this Octave session, as a struct (after the
## change, when one is asked for).
##
## Sizes over a limit are refused before anything is computed or allocated, with the error
## @code{cagd:limit} naming the limit (the same limits as the command line's @code{--max-*}
## flags, the library's @code{cagd::limits::Limits}):
## @table @code
## @item max_samples
## parameter values along one axis (e.g. @var{N} of @code{deCasteljau}), default 1 000 000;
## @item max_grid_points
## points of a surface grid, default 10 000 000;
## @item max_degree
## degree of a curve, patch direction or basis, number of nodes − 1, default 1000;
## @item max_work
## arithmetic operations of one call, estimated up front by the library's own estimates (the
## command line's and the page's, so that each refuses the same work with the same words;
## exact fractions weigh more), default 2e9;
## @item max_expression_bytes, max_depth, max_elements
## text read in exact mode (@code{"[0 1/3 1]"});
## @item max_input_bytes, max_iterations, max_system_entries
## kept for the library's other readers.
## @end table
##
## A long computation allowed by raised limits can be stopped with Ctrl-C, as Octave's own
## functions are: the package asks Octave every few milliseconds of work.
##
## Example:
## @example
## @group
## cagd_limits ("max_samples", 10);
## deCasteljau ([0 1], 11)
##   @print{} error: deCasteljau: N: 11 exceeds the limit of 10 (raise it with cagd_limits ("max_samples", VALUE))
## cagd_limits ("default");
## @end group
## @end example
## @end deftypefn

function L = cagd_limits (varargin)
  [names, values] = __cagd__ ("cagd_limits", varargin{:});
  L = cell2struct (num2cell (values), names, 1);
endfunction

%!test
%! unwind_protect
%!   L = cagd_limits ("max_samples", 10);
%!   assert (L.max_samples, 10);
%!   assert (cagd_limits ().max_samples, 10);
%!   fail ("deCasteljau ([0 1], 11)", "N: 11 exceeds the limit of 10");
%!   assert (size (deCasteljau ([0 1], 10)), [1 10]);
%! unwind_protect_cleanup
%!   cagd_limits ("default");
%! end_unwind_protect
%! assert (cagd_limits ().max_samples, 1e6);
%! assert (size (deCasteljau ([0 1], 11)), [1 11]);
%!error <no limit 'samples'> cagd_limits ("samples", 10)
%!error <VALUE: 0; expected a positive integer> cagd_limits ("max_degree", 0)

%!demo
%! ## The session's resource limits (a grid too large for them is refused before any work).
%! L = cagd_limits ()
%! cagd_limits ("max_samples", 10);
%! try, deCasteljau ([0 1], 11); catch err, disp (err.message); end
%! cagd_limits ("default");
