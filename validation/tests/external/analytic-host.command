# The command template stipple-validate may run for external-renderer.yaml (--renderer-command): one argument per
# line, the program first (--renderer replaces it). A matrix's template runs only when it equals this one.
analytic_host
--pattern
{pattern}
--spp
{spp}
--seed
{seed}
--width
{width}
--height
{height}
--output
{output}
