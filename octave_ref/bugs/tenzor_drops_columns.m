% Bug: tenzor silently drops trailing columns when size(B,2) is not a multiple of 3: n is
% fractional and the loop l = 1:n+1 stops at floor(n+1).
bug_setup;
for B = {reshape(1:14, 2, 7), reshape(1:10, 2, 5)}
    A = tenzor(B{1});
    printf('B is %dx%d: n = %g, A = tenzor(B) is %s, last column of B kept: %d\n', ...
           size(B{1}), columns(B{1})/3 - 1, mat2str(size(A)), any(A(:) == B{1}(end)));
end;
