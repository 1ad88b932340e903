-- wrk's requests for bench/serve_load.sh: FRUSTUM_MODE=preview or submit, spread over the
-- sessions in the file FRUSTUM_SESSIONS (a Lua table {{cookie=…, csrf=…}, …}).
local sessions = dofile(os.getenv("FRUSTUM_SESSIONS"))
local mode = os.getenv("FRUSTUM_MODE")
local n = 0

request = function()
  n = n + 1
  local s = sessions[(n % #sessions) + 1]
  local headers = {
    ["Cookie"] = "frustum_session=" .. s.cookie,
    ["Content-Type"] = "application/x-www-form-urlencoded",
    ["Accept"] = "application/json",
  }
  if mode == "preview" then
    local body = "csrf=" .. s.csrf .. "&set=week1&problem=zbuf&answer=plane&text=x%2By-z%3D" .. (n % 97)
    return wrk.format("POST", "/api/preview", headers, body)
  end
  local body = "csrf=" .. s.csrf .. "&problem=zbuf&a.plane=x%2By-z%3D6&a.z=" .. (n % 50)
  return wrk.format("POST", "/set/week1/submit", headers, body)
end
