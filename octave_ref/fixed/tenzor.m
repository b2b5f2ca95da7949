% tenzor.m -- minimally fixed version of ../original/tenzor.m (thesis appendix B, Algoritem 4).
%
% A = tenzor(B)
%   B   (m+1) x 3(n+1): a packed net, row k holds the points b(k-1,0), ..., b(k-1,n) one after
%       the other as x y z triples: B(k, 3*l-2:3*l) = b(k-1,l-1).
%   A   (m+1) x (n+1) x 3: A(k,l,:) = b(k-1,l-1).
%
% What was changed, and why:
%   1. The number of columns must be a multiple of 3: the original computed a fractional n and
%      silently dropped the trailing columns; now that is an error.
%   2. A is preallocated as zeros(m+1,n+1,3), so the result always has its full shape and the
%      loop does not grow A element by element.
%   3. The function is closed with "end;" (the original relied on end-of-file).
% The copying itself is the original's.
function A=tenzor(B)
if mod(size(B)(2),3) != 0
    error('tenzor: the number of columns of B (%d) is not a multiple of 3', size(B)(2));
end;
m=size(B)(1)-1;
n=(size(B)(2)/3) -1;
A = zeros(m+1,n+1,3);
for k=1: m+1
    for l=1: n+1
        A(k,l,:)= B(k,3*l-2:3*l);
    end;
end;
end;
