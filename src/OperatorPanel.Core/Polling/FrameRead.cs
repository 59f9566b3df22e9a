using System.Collections.Immutable;

namespace OperatorPanel.Core.Polling;

/// <summary>What one READ of a cycle brought: the reply data, or the error and whether the station refused or went silent.</summary>
internal readonly record struct FrameRead(ImmutableArray<byte> Data, string? Error, bool Refused, bool StationOffline)
{
    public bool Succeeded => !Data.IsDefault;

    public static FrameRead Success(ImmutableArray<byte> data) => new(data, null, false, false);

    public static FrameRead Refusal(string error) => new(default, error, true, false);

    public static FrameRead Failure(string error, bool stationOffline) => new(default, error, false, stationOffline);
}
