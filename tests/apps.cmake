# tests of this module are added in the next commit
