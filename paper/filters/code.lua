-- Code shown in the document is pulled from src/ when the document is built, never pasted:
--   ```{.cpp file="src/schemes.cpp" region="linear-scheme"}
--   ```
-- is replaced by the lines between "// @region linear-scheme" and "// @end linear-scheme" in
-- that file, with a caption line naming the file and the lines. A missing file or region stops
-- the build (so does a region that is opened twice or never closed). A listing longer than
-- kFoldLines lines is shown closed on screen, under the line its attribute fold="The code of ..."
-- gives, and opens when the page is printed (paper/print.html): paper has no click to open it.
local kFoldLines = 40

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
  local lines = select(2, text:gsub("\n", "")) + 1
  -- A short listing is kept on one printed page; a long one may run on, rather than leave half a page blank.
  local listing = pandoc.Div({caption, pandoc.CodeBlock(text, {class = "cpp"})},
                             {class = lines <= 15 and "listing short" or "listing"})
  -- On screen a long listing stays out of the way, closed under its fold line; a short one is
  -- read where it stands.
  local fold = el.attributes["fold"]
  if lines <= kFoldLines then
    if fold then error("code.lua: region " .. name .. " has " .. lines .. " lines and is never folded: drop its fold=") end
    return listing
  end
  if not fold then error("code.lua: region " .. name .. " has " .. lines .. " lines and no fold=\"...\" line to open it") end
  return pandoc.Div({
    pandoc.RawBlock("html", "<details><summary>" .. fold .. " (" .. lines .. " lines)</summary>"),
    listing,
    pandoc.RawBlock("html", "</details>"),
  }, {class = "folded"})
end
