-- Numbers in the prose are never typed: the text says {{table.linear_error_over_tol_max}} and this
-- filter puts in the value that build/prose_numbers derived from results/ (results/numbers.csv,
-- and results/numbers_machine.csv for timings and package versions). A key that neither file has stops the build, so
-- the document cannot show a number whose source is gone. Code is left alone.
local values = {}

local function load(path)
  local f = io.open(path, "r")
  if not f then error("numbers.lua: cannot open " .. path .. " (run make paper, which writes it)") end
  for line in f:lines() do
    if not line:match("^#") and line ~= "key,value,source" then
      local key, value = line:match("^([^,]+),([^,]*),")
      if not key then error("numbers.lua: bad line in " .. path .. ": " .. line) end
      values[key] = value
    end
  end
  f:close()
end

load("results/numbers.csv")
load("results/numbers_machine.csv")

local function fill(text)
  return (text:gsub("{{([%w_%.%-%+]+)}}", function(key)
    local v = values[key]
    if v == nil then error("numbers.lua: no number " .. key .. " in results/numbers*.csv") end
    return v
  end))
end

-- Pandoc splits "{{a}}-{{b}}" into several Str; each one carries whole keys, since keys hold no spaces.
-- A value like 8.3e-04 must not break after its "e-": it goes in the span the style sheet keeps whole.
function Str(el)
  el.text = fill(el.text)
  if el.text:match("%de[+%-]%d") then return pandoc.Span({ el }, { class = "num" }) end
  return el
end
function Math(el) el.text = fill(el.text); return el end
function RawInline(el) el.text = fill(el.text); return el end
