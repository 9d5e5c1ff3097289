# methods.gp - the colour and marker of the m-th method of a figure
# (m = 1, 2, ... in order of first appearance in the data):
#   load 'plots/methods.gp'
#   mk_color(m)   one of 12 colours, (m - 1) % 12
#   mk_pt(m)      one of 7 filled markers, (m - 1) % 7
# 12 and 7 share no factor, so the (colour, marker) pair differs for every
# two of the first mk_styles = 84 methods: each method has its own look.
mk_styles = 84
mk_color(m) = word("#1b6ca8 #d1495b #edae49 #00798c #6a994e #8e7dbe #5fa8d3 #3d405b #f4845f #2a9d8f #bc4749 #6d597a", (m - 1) % 12 + 1)
mk_pt(m) = word("7 5 9 11 13 15 3", (m - 1) % 7 + 1) + 0
