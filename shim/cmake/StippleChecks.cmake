# StippleChecks.cmake — CTest checks of the library as a product (placeholder filled below).
