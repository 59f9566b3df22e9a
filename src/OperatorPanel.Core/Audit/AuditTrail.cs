using Serilog;
using Serilog.Core;

namespace OperatorPanel.Core.Audit;

/// <summary>Ready-made trails: none (tests, tools that change no PLC), and one that feeds several keepers.</summary>
public static class AuditTrail
{
    /// <summary>Keeps nothing and refuses nothing.</summary>
    public static IAuditTrail None { get; } = new NoTrail();

    /// <summary>
    /// Records in <paramref name="primary"/> first, which decides (its refusal stops the action); then in each of
    /// <paramref name="others"/> (a historian), whose failures are logged and do not stop the action.
    /// </summary>
    public static IAuditTrail Combine(IAuditTrail primary, IEnumerable<IAuditTrail> others, ILogger? logger = null)
    {
        ArgumentNullException.ThrowIfNull(primary);
        ArgumentNullException.ThrowIfNull(others);
        return new Combined(primary, [.. others], logger ?? Logger.None);
    }

    private sealed class NoTrail : IAuditTrail
    {
        public ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken) => ValueTask.FromResult<string?>(null);
    }

    private sealed class Combined(IAuditTrail primary, IAuditTrail[] others, ILogger logger) : IAuditTrail
    {
        public async ValueTask<string?> RecordAsync(AuditEntry entry, CancellationToken cancellationToken)
        {
            if (await primary.RecordAsync(entry, cancellationToken).ConfigureAwait(false) is { } refused)
            {
                return refused;
            }

            foreach (var other in others)
            {
                if (await other.RecordAsync(entry, cancellationToken).ConfigureAwait(false) is { } failed)
                {
                    logger.Warning("Audit {Step} of {Action} {Entry:l} not kept by {Keeper}: {Reason:l}", entry.Step, entry.Action, entry.Describe(), other.GetType().Name, failed);
                }
            }

            return null;
        }
    }
}
