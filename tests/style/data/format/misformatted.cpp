// Fixture: a file out of the tree's clang-format style.
int  misformatted( int x ){return x*2;}
