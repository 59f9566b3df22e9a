namespace OperatorPanel.Core.Tests.Projects;

/// <summary>
/// A test of Linux file permissions (folder modes, chattr), reported as skipped with its reason on Windows, never passed
/// in silence: Windows ignores a folder's Read-only attribute and has no chattr. With <see cref="NeedsRoot"/> also
/// skipped, with the reason, for a user who may not run chattr +i.
/// </summary>
[AttributeUsage(AttributeTargets.Method)]
internal sealed class UnixFactAttribute : FactAttribute
{
    private bool _needsRoot;

    public UnixFactAttribute()
    {
        if (OperatingSystem.IsWindows())
        {
            Skip = "Linux file permissions: Windows ignores a folder's Read-only attribute";
        }
    }

    public bool NeedsRoot
    {
        get => _needsRoot;
        set
        {
            _needsRoot = value;
            if (value && !OperatingSystem.IsWindows() && !Environment.IsPrivilegedProcess)
            {
                Skip = "chattr +i needs root";
            }
        }
    }
}
