% Bug: appendix D's data script uses u and v (in c0 = [u;0;u-u^2], ...) without defining them.
bug_setup;
krpaGordon_data;
