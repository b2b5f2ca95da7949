% [ok, s] = cagd_close (a, b) -- compare two numeric arrays as the package's tests do:
% each element within 4 ULPs, or within 1e-14 relative to the scale of the array (its largest
% magnitude).  s holds the counts and the worst errors, and accumulates when passed back in:
% [ok, s] = cagd_close (a, b, s).
%   s.n          elements compared         s.identical  of them bit for bit equal
%   s.ulps       worst distance in ULPs    s.rel        worst |a-b| / scale
function [ok, s] = cagd_close (a, b, s)
  if nargin < 3
    s = struct ("n", 0, "identical", 0, "ulps", 0, "rel", 0);
  end
  if ! isequal (size (a), size (b))
    ok = false;
    return;
  end
  a = a(:); b = b(:);
  d = abs (a - b);
  scale = max ([abs(b); abs(a); realmin]);
  ulps = d ./ eps (max (abs (a), abs (b)));
  ulps(d == 0) = 0;
  rel = d / scale;
  ok = all ((ulps <= 4) | (rel <= 1e-14));
  s.n += numel (a);
  s.identical += sum (d == 0);
  s.ulps = max ([s.ulps; ulps]);
  s.rel = max ([s.rel; rel]);
end
