% Bug: appendix C's data script for vrednostCoons uses u and v without defining them.
bug_setup;
vrednostCoons_data;
