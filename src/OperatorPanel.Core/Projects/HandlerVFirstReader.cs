using System.Globalization;
using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Protocol.V3;

namespace OperatorPanel.Core.Projects;

/// <summary>
/// Reads a station's optional <c>"handlerVFirst"</c>: a whole number, where the station's handler (full or compact, as
/// its "compact" says) fits in its CPU's V by the generator's own rule (<see cref="HandlerPlace"/>, STL005), so the
/// project never records a place generate would refuse.
/// </summary>
internal static class HandlerVFirstReader
{
    public const string Name = "handlerVFirst";

    /// <summary>False when the property is there and wrong (reported).</summary>
    /// <param name="fields">The station.</param>
    /// <param name="cpu">The station's CPU; null when unreadable (reported), so only the lowest byte is checked.</param>
    /// <param name="compact">The station's "compact"; null when unreadable (reported), so only the lowest byte is checked.</param>
    /// <param name="vFirst">The value; null when the property is absent (the default place) or wrong.</param>
    public static bool TryRead(JsonFields fields, CpuProfile? cpu, bool? compact, out int? vFirst)
    {
        vFirst = null;
        if (!fields.Has(Name))
        {
            return true;
        }

        if (fields.Int(Name) is not { } value)
        {
            return false;
        }

        var problem = cpu is not null && compact is { } isCompact
            ? Problem(value, HandlerShape.Of(isCompact), cpu, isCompact)
            : value < HandlerPlace.LowestVFirst
                ? string.Create(CultureInfo.InvariantCulture, $"{value}: a protocol 3 handler starts at VB{HandlerPlace.LowestVFirst} or later (its frame check points 3 bytes before its V bytes)")
                : null;
        if (problem is not null)
        {
            fields.Problem(Name, problem);
            return false;
        }

        vFirst = value;
        return true;
    }

    private static string? Problem(int value, HandlerShape shape, CpuProfile cpu, bool compact)
    {
        if (HandlerPlace.Problem(value, shape, cpu) is not { } problem)
        {
            return null;
        }

        // The generator's sentence names a range of V bytes; a negative number names none ("VB-4").
        var what = value < 0 ? string.Create(CultureInfo.InvariantCulture, $"{value} is not a V byte") : problem;
        return string.Create(CultureInfo.InvariantCulture,
            $"{what}; \"{Name}\" may be {HandlerPlace.LowestVFirst}-{HandlerPlace.HighestVFirst(shape, HandlerPlace.VBytes(cpu))} "
            + $"for the {(compact ? "compact" : "full")} handler (leave it out for the top of V, where generate puts it by default)");
    }
}
