% deCasteljau.m -- minimally fixed version of ../original/deCasteljau.m
% (thesis appendix A, Algoritem 1).
%
% T = deCasteljau(kontrolneT, N)
%   kontrolneT  d x (n+1): one control point per COLUMN (row 1 = x, row 2 = y, ...), as the
%               plotting code of the original reads them; any dimension d >= 1.
%   N           number of samples; the curve is evaluated at linspace(0,1,N).
%   T           d x N: T(:,k) is the point of the curve at s(k) = linspace(0,1,N)(k).
%
% What was changed, and why:
%   1. Returns T (new output "T = ...") and no longer plots (lines 15-20 of the original removed):
%      plotting belongs to the command line; the reference files need the numbers.
%   2. Row/column mix-up: the original interpolated ROWS (kontrolneT(i,:)), i.e. coordinates,
%      while the points are the COLUMNS; with more than 3 control points it fails with
%      "index (4,_): out of bound".  Now it interpolates columns: b(:,i) = (1-t)*b(:,i)+t*b(:,i+1).
%   3. Number of levels: the outer loop ran j = 1:m with m = number of rows (the dimension);
%      a curve with n control points needs n-1 levels, so j = 1:(n-1).
%   4. In-place overwrite: the original overwrote kontrolneT itself, so every parameter t after
%      the first started from the previous t's scheme instead of the control points (and the
%      "control polygon" it plotted afterwards was garbage).  Now each t works on a fresh copy b.
%   5. T = zeros(m,N) with m = number of rows instead of zeros(3,N), so any dimension works.
% Kept as in the original: the inner loop runs over i = 1:(n-1) at every level; entries past
% n-j are computed but never reach b(:,1), so the result equals the scheme (2.1) of the thesis.
% The arithmetic of each step, (1-t)*b_i + t*b_(i+1), is the original's, term for term.
function T = deCasteljau(kontrolneT,N)
m = size(kontrolneT)(1);
n = size(kontrolneT)(2);
T = zeros(m,N);
s = linspace(0,1,N);
for k = 1:N
    t = s(k);
    b = kontrolneT;
    for j = 1:(n-1)
        for i = 1:(n-1)
            b(:,i) = (1-t)*b(:,i)+t*b(:,i+1);
        end;
    end;
    T(:,[k]) = b(:,[1]);
end;
end;
