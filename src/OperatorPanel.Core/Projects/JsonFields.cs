using System.Collections.Immutable;
using System.Diagnostics.CodeAnalysis;
using System.Text.Json;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// The properties of one JSON object, read by name with their type checked. Every wrong, missing, duplicated or
/// unknown property becomes a problem at its JSON path; a getter that found a problem returns null so the caller
/// carries on with the next property and the user sees every problem in one pass.
/// </summary>
internal sealed class JsonFields
{
    private readonly Dictionary<string, JsonElement> _values = new(StringComparer.Ordinal);
    private readonly ProjectProblems _problems;

    private JsonFields(string path, ProjectProblems problems)
    {
        Path = path;
        _problems = problems;
    }

    public string Path { get; }

    public ProjectProblems Problems => _problems;

    public static JsonFields? Open(JsonElement element, string path, ProjectProblems problems)
    {
        if (element.ValueKind != JsonValueKind.Object)
        {
            problems.Add(path, $"expected an object, found {Describe(element)}");
            return null;
        }

        var fields = new JsonFields(path, problems);
        foreach (var property in element.EnumerateObject())
        {
            if (!TryText(() => property.Name, out var name))
            {
                problems.Add(path, "a property name is not valid Unicode text");
            }
            else if (!fields._values.TryAdd(name, property.Value))
            {
                problems.Add(JsonPath.Property(path, name), "this property appears more than once");
            }
        }

        return fields;
    }

    /// <summary>Reports properties outside <paramref name="known"/>: most often a typing mistake in a hand-edited file.</summary>
    public void ReportUnknown(params string[] known)
    {
        foreach (var name in _values.Keys.Where(n => !known.Contains(n, StringComparer.Ordinal)))
        {
            _problems.Add(At(name), $"unknown property '{JsonPath.Shorten(name)}'; expected {string.Join(", ", known)}");
        }
    }

    public string At(string name) => JsonPath.Property(Path, name);

    public void Problem(string name, string message) => _problems.Add(At(name), message);

    /// <summary>A string property; required unless <paramref name="fallback"/> is given.</summary>
    public string? String(string name, string? fallback = null)
    {
        if (!TryValue(name, fallback is null, out var value))
        {
            return fallback;
        }

        if (value.ValueKind != JsonValueKind.String)
        {
            Wrong(name, "a string", value);
            return null;
        }

        if (!TryText(value.GetString, out var text))
        {
            Problem(name, "the string is not valid Unicode text");
            return null;
        }

        return text;
    }

    /// <summary>An optional enum written as a camelCase word ("radioModule").</summary>
    public T? Word<T>(string name, T fallback)
        where T : struct, Enum => WordCore<T>(name, JsonWords.Of(fallback));

    /// <summary>A required enum written as a camelCase word.</summary>
    public T? Word<T>(string name)
        where T : struct, Enum => WordCore<T>(name, fallback: null);

    /// <summary>A whole-number property; required unless <paramref name="fallback"/> is given.</summary>
    public int? Int(string name, int? fallback = null)
    {
        if (!TryValue(name, fallback is null, out var value))
        {
            return fallback;
        }

        if (value.ValueKind != JsonValueKind.Number)
        {
            Wrong(name, "a whole number", value);
            return null;
        }

        if (value.TryGetInt32(out var number))
        {
            return number;
        }

        var raw = value.GetRawText();
        Problem(name, raw.Contains('.', StringComparison.Ordinal) || raw.Contains('e', StringComparison.OrdinalIgnoreCase)
            ? $"expected a whole number, found {JsonPath.Shorten(raw)}"
            : $"{JsonPath.Shorten(raw)} is far outside any allowed range");
        return null;
    }

    /// <summary>True when the entry has the property at all (optional properties that change a tag's meaning, an optional object read only when present).</summary>
    public bool Has(string name) => _values.ContainsKey(name);

    /// <summary>A number, whole or not (a scale, a range end); required. Null when missing or wrong (reported).</summary>
    public double? Number(string name)
    {
        if (!TryValue(name, required: true, out var value))
        {
            return null;
        }

        if (value.ValueKind != JsonValueKind.Number)
        {
            Wrong(name, "a number", value);
            return null;
        }

        if (!value.TryGetDouble(out var number) || !double.IsFinite(number))
        {
            Problem(name, $"{JsonPath.Shorten(value.GetRawText())} is far outside any allowed range");
            return null;
        }

        return number;
    }

    public bool? Bool(string name, bool fallback)
    {
        if (!TryValue(name, required: false, out var value))
        {
            return fallback;
        }

        if (value.ValueKind is JsonValueKind.True or JsonValueKind.False)
        {
            return value.ValueKind == JsonValueKind.True;
        }

        Wrong(name, "true or false", value);
        return null;
    }

    /// <summary>A number, whole or not (a deadband of 0.5); optional, <paramref name="fallback"/> when missing.</summary>
    public double? Number(string name, double fallback) =>
        TryNullableNumber(name, out var value) ? value ?? fallback : null;

    /// <summary>
    /// An optional number that may also be written null (both mean "not set": <paramref name="value"/> null); false when
    /// the property holds anything else, with the problem reported.
    /// </summary>
    public bool TryNullableNumber(string name, out double? value)
    {
        value = null;
        if (!TryValue(name, required: false, out var element) || element.ValueKind == JsonValueKind.Null)
        {
            return true;
        }

        if (element.ValueKind != JsonValueKind.Number || !element.TryGetDouble(out var number) || !double.IsFinite(number))
        {
            Wrong(name, "a number", element);
            return false;
        }

        value = number;
        return true;
    }

    /// <summary>A required nested object.</summary>
    public JsonFields? Object(string name) =>
        TryValue(name, required: true, out var value) ? Open(value, At(name), _problems) : null;

    /// <summary>An array property with each element's path; a missing optional array is empty.</summary>
    /// <summary>
    /// Reads an optional array of objects with <paramref name="read"/>, one entry at a time, so every entry's problems
    /// are reported. Null when the array is missing or malformed, or when any entry had a problem.
    /// </summary>
    public ImmutableArray<T>? Entries<T>(string name, Func<JsonFields, T?> read)
        where T : class
    {
        var elements = Array(name, required: false);
        if (elements is null)
        {
            return null;
        }

        var entries = new List<T>();
        var complete = true;
        foreach (var (element, path) in elements)
        {
            if (_problems.IsFull)
            {
                return null;
            }

            var entry = Open(element, path, _problems);
            var value = entry is null ? null : read(entry);
            complete &= value is not null;
            if (value is not null)
            {
                entries.Add(value);
            }
        }

        return complete ? [.. entries] : null;
    }

    public IReadOnlyList<(JsonElement Element, string Path)>? Array(string name, bool required)
    {
        if (!TryValue(name, required, out var value))
        {
            return required ? null : [];
        }

        if (value.ValueKind != JsonValueKind.Array)
        {
            Problem(name, $"expected an array, found {Describe(value)}");
            return null;
        }

        return [.. value.EnumerateArray().Select((element, index) => (element, JsonPath.Index(At(name), index)))];
    }

    public static string Describe(JsonElement value) => value.ValueKind switch
    {
        JsonValueKind.Object => "an object",
        JsonValueKind.Array => "an array",
        JsonValueKind.String => "the string " + JsonPath.Shorten(value.GetRawText()),
        JsonValueKind.Number => "the number " + JsonPath.Shorten(value.GetRawText()),
        JsonValueKind.Null => "null",
        _ => value.GetRawText(),
    };

    private bool TryValue(string name, bool required, out JsonElement value)
    {
        if (_values.TryGetValue(name, out value))
        {
            return true;
        }

        if (required)
        {
            _problems.Add(Path, $"missing required property '{name}'");
        }

        return false;
    }

    private T? WordCore<T>(string name, string? fallback)
        where T : struct, Enum
    {
        var text = String(name, fallback);
        if (text is null)
        {
            return null;
        }

        if (JsonWords.TryParse<T>(text, out var value))
        {
            return value;
        }

        Problem(name, $"unknown {name} '{JsonPath.Shorten(text)}'; use {JsonWords.List<T>()}");
        return null;
    }

    private void Wrong(string name, string expected, JsonElement found) =>
        Problem(name, $"expected {expected}, found {Describe(found)}");

    /// <summary>
    /// System.Text.Json refuses to turn an escaped lone surrogate ("\uD800") into a .NET string with an
    /// InvalidOperationException; that is bad input, so it becomes a problem here instead of escaping the loader.
    /// </summary>
    private static bool TryText(Func<string?> read, [NotNullWhen(true)] out string? text)
    {
        try
        {
            text = read() ?? string.Empty;
            return true;
        }
        catch (InvalidOperationException)
        {
            text = null;
            return false;
        }
    }
}
