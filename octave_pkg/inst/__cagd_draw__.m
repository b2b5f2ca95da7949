## -*- texinfo -*-
## @deftypefn {} {} __cagd_draw__ (@var{what}, @dots{})
## Internal: the figures the thesis functions drew when called without an output argument,
## with Octave's own @code{plot3} and @code{surf}.
##
## @table @code
## @item __cagd_draw__ ("curve", @var{T}, @var{P})
## the curve @var{T} (@math{d × N}) and the control polygon @var{P} with its points in red
## (@code{deCasteljau}); plane curves with @code{plot}, 1-D curves against the parameter.
## @item __cagd_draw__ ("surface", @var{P})
## the surface @var{P} (@math{N × N × 3}) with @code{surf} (@code{ploskevB}, @code{krpaGordon}).
## @item __cagd_draw__ ("coons", @var{P}, @var{c1}, @var{c2}, @var{d1}, @var{d2})
## the surface and its boundary curves, @var{c1} and @var{c2} red, @var{d1} and @var{d2} green,
## line width 2.5 (@code{krpaCoons}).
## @end table
## The hold state of the axes is restored afterwards (the original left @code{hold on}).
## @end deftypefn

function __cagd_draw__ (what, varargin)
  was_held = ishold ();
  unwind_protect
    switch (what)
      case "curve"
        [T, P] = deal (varargin{:});
        switch (rows (T))
          case 1
            t = linspace (0, 1, columns (T));
            plot (t, T);
            hold on;
            tp = linspace (0, 1, columns (P));
            plot (tp, P, "ro", tp, P, "r");
          case 2
            plot (T(1,:), T(2,:));
            hold on;
            plot (P(1,:), P(2,:), "ro");
            plot (P(1,:), P(2,:), "r");
          otherwise
            plot3 (T(1,:), T(2,:), T(3,:));
            hold on;
            plot3 (P(1,:), P(2,:), P(3,:), "ro");
            plot3 (P(1,:), P(2,:), P(3,:), "r");
        endswitch
      case "surface"
        P = varargin{1};
        surf (P(:,:,1), P(:,:,2), P(:,:,3));
      case "coons"
        [P, c1, c2, d1, d2] = deal (varargin{:});
        surf (P(:,:,1), P(:,:,2), P(:,:,3));
        hold on;
        plot3 (c1(1,:), c1(2,:), c1(3,:), "r", "LineWidth", 2.5);
        plot3 (c2(1,:), c2(2,:), c2(3,:), "r", "LineWidth", 2.5);
        plot3 (d1(1,:), d1(2,:), d1(3,:), "g", "LineWidth", 2.5);
        plot3 (d2(1,:), d2(2,:), d2(3,:), "g", "LineWidth", 2.5);
      otherwise
        error ("cagd:value", "__cagd_draw__: unknown drawing '%s'", what);
    endswitch
  unwind_protect_cleanup
    if (! was_held)
      hold off;
    endif
  end_unwind_protect
endfunction
