-- Code shown in the document is pulled from src/ when the document is built, never pasted:
--   ```{.cpp file="src/schemes.cpp" region="linear-scheme"}
--   ```
-- is replaced by the lines between "// @region linear-scheme" and "// @end linear-scheme" in
-- that file, with a caption line naming the file and the lines. A missing file or region stops
-- the build (so does a region that is opened twice or never closed). An attribute
-- fold="The code of ..." shows the listing closed, under that line.
local function read_lines(path)
  local f = io.open(path, "r")
  if not f then error("code.lua: cannot open " .. path) end
  local lines = {}
  for line in f:lines() do lines[#lines + 1] = line end
  f:close()
  return lines
end

local function region(path, name)
  local lines = read_lines(path)
  local first, last
  for i, line in ipairs(lines) do
    local open = line:match("//%s*@region%s+([%w%-_]+)%s*$")
    local close = line:match("//%s*@end%s+([%w%-_]+)%s*$")
    if open == name then
      if first then error("code.lua: region " .. name .. " opened twice in " .. path) end
      first = i
    elseif close == name then
      if not first then error("code.lua: region " .. name .. " closed before it opens in " .. path) end
      last = i
      break
    end
  end
  if not first then error("code.lua: no region " .. name .. " in " .. path) end
  if not last then error("code.lua: region " .. name .. " is never closed in " .. path) end
  local body = {}
  for i = first + 1, last - 1 do
    if not lines[i]:match("//%s*@region") and not lines[i]:match("//%s*@end") then body[#body + 1] = lines[i] end
  end
  return table.concat(body, "\n"), first + 1, last - 1
end

function CodeBlock(el)
  local path, name = el.attributes["file"], el.attributes["region"]
  if not path then return nil end
  if not name then error("code.lua: a code block names file " .. path .. " but no region") end
  local text, a, b = region(path, name)
  local caption = pandoc.Para({pandoc.Code(path), pandoc.Str((a == b and ", line " .. a or ", lines " .. a .. "–" .. b) .. " (region "),
                               pandoc.Code(name), pandoc.Str(")")})
  local listing = pandoc.Div({caption, pandoc.CodeBlock(text, {class = "cpp"})}, {class = "listing"})
  -- fold="..." keeps a long listing out of the reader's way: closed, with that line to open it.
  local fold = el.attributes["fold"]
  if not fold then return listing end
  local lines = select(2, text:gsub("\n", "")) + 1
  return pandoc.Div({
    pandoc.RawBlock("html", "<details><summary>" .. fold .. " (" .. lines .. " lines)</summary>"),
    listing,
    pandoc.RawBlock("html", "</details>"),
  }, {class = "folded"})
end
